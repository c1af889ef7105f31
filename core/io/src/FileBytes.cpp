#include "tofsim/io/FileBytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>

#include "NpyHeader.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

namespace {
// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};
}  // namespace

std::string readFileNoFollow(const std::filesystem::path& path, std::size_t maxBytes) {
  const std::string name = path.string();
  const Fd f{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK)};
  if (f.fd < 0) {
    const int e = errno;
    throw InputError(FileLoc{name}, "",
                     e == ELOOP ? "is a symbolic link (input files are not read through links)"
                                : std::string("cannot open: ") + std::strerror(e));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    throw InputError(FileLoc{name}, "", "is not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > maxBytes) {
    throw InputError(FileLoc{name}, "",
                     "is " + std::to_string(st.st_size) + " bytes, over the " +
                         std::to_string(maxBytes) + " this input may have");
  }
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(f.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InputError(FileLoc{name}, "", "read failed");
    got += static_cast<std::size_t>(n);
  }
  return bytes;
}

}  // namespace tofsim::io
