#include "Warning.h"

#include <cstdio>
#include <mutex>

namespace tofsim::pipeline {

namespace {

struct Seen {
  std::mutex mutex;
  int scopes = 0;
  std::set<std::string> printed;
  std::size_t held = 0;
};

Seen& seen() {
  static Seen s;
  return s;
}

}  // namespace

void warn(const std::string& text) {
  Seen& s = seen();
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (s.scopes > 0 && !s.printed.insert(text).second) {
    ++s.held;
    return;
  }
  std::fprintf(stderr, "tofsim: warning: %s\n", text.c_str());
}

RepeatedWarningsOnce::RepeatedWarningsOnce() {
  const std::lock_guard<std::mutex> lock(seen().mutex);
  ++seen().scopes;
}

RepeatedWarningsOnce::~RepeatedWarningsOnce() {
  Seen& s = seen();
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (--s.scopes > 0) return;
  if (s.held > 0) {
    std::fprintf(stderr, "tofsim: (%zu repeats of the warnings above not shown)\n", s.held);
  }
  s.printed.clear();
  s.held = 0;
}

}  // namespace tofsim::pipeline
