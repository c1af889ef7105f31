#include "tofsim/util/Error.h"

#include <cstdio>
#include <cstdlib>

namespace tofsim {

std::string FileLoc::toString() const {
  std::string s = file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  return s;
}

namespace {
std::string compose(const FileLoc& loc, const std::string& key, const std::string& message) {
  std::string s;
  const std::string where = loc.toString();
  if (!where.empty()) s += where + ": ";
  if (!key.empty()) s += key + ": ";
  return s + message;
}
}  // namespace

InputError::InputError(const std::string& message) : std::runtime_error(message) {}

InputError::InputError(const FileLoc& loc, const std::string& key, const std::string& message)
    : std::runtime_error(compose(loc, key, message)), loc_(loc), key_(key) {}

void checkFailed(const char* expr, const char* file, int line, const std::string& detail) {
  std::fprintf(stderr, "tofsim internal error: CHECK(%s) failed at %s:%d%s%s\n", expr, file, line,
               detail.empty() ? "" : ": ", detail.c_str());
  std::abort();
}

}  // namespace tofsim
