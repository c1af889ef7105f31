#include "tofsim/util/FolderPath.h"

namespace tofsim {

namespace fs = std::filesystem;

std::string folderPathProblem(const fs::path& folder) {
  std::error_code ec;
  fs::path target = fs::absolute(folder, ec).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/" is "out"
  for (fs::path p = target;; p = p.parent_path()) {
    const fs::file_status s = fs::status(p, ec);
    if (s.type() == fs::file_type::directory) return "";
    if (s.type() != fs::file_type::not_found) {  // (a path through a file is not_found)
      if (ec) return p.string() + ": " + ec.message();
      const std::string what =
          p.string() + (s.type() == fs::file_type::regular ? " is a file" : " is not a folder");
      return p == target ? what + ", not a folder"
                         : what + ", so the folder " + target.string() + " cannot be made in it";
    }
    if (p == p.parent_path()) return "";  // nothing exists up to the root: create_directories says
  }
}

}  // namespace tofsim
