#include "VideoModule.h"

#include <dlfcn.h>

#include <cerrno>  // program_invocation_name
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string_view>
#include <system_error>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::imaging::detail {

namespace {

struct Module {
  void* (*open)(const char*, double, int, int) = nullptr;
  void (*write)(void*, const unsigned char*, int, int, unsigned long) = nullptr;
  void (*close)(void*) = nullptr;
};

std::vector<std::string> splitFolders(std::string_view list) {
  std::vector<std::string> folders;
  while (!list.empty()) {
    const size_t colon = list.find(':');
    if (colon != 0) folders.emplace_back(list.substr(0, colon));
    if (colon == std::string_view::npos) break;
    list.remove_prefix(colon + 1);
  }
  return folders;
}

// The folder of the binary that holds this code: the executable (`tofsim`, a
// program linking the static library) or the shared object (the Python
// module). dladdr names the main program by its argv[0], so that one comes
// from /proc/self/exe. Empty when neither says.
std::filesystem::path ownFolder() {
  static const char anchor = 0;
  Dl_info info{};
  if (dladdr(&anchor, &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  std::filesystem::path self;
  if (*info.dli_fname == '\0' || std::strcmp(info.dli_fname, program_invocation_name) == 0) {
    self = std::filesystem::read_symlink("/proc/self/exe", ec);
  } else {
    self = std::filesystem::weakly_canonical(info.dli_fname, ec);
  }
  return ec ? std::filesystem::path() : self.parent_path();
}

// Where the module may be, first choice first: the environment's
// TOFSIM_VIDEO_MODULE; beside an installed binary (bin/../lib/tofsim, or from
// the installed Python package); this build tree's; the install prefixes'
// (a program linking an installed tofsim). apps/imaging/CMakeLists.txt sets them.
std::vector<std::string> moduleCandidates() {
  if (const char* p = std::getenv("TOFSIM_VIDEO_MODULE"); p != nullptr && *p != '\0') return {p};
  std::vector<std::string> candidates;
  if (const std::filesystem::path own = ownFolder(); !own.empty()) {
    for (const std::string& relative : splitFolders(TOFSIM_VIDEO_MODULE_RELATIVE_DIRS)) {
      candidates.push_back((own / relative / TOFSIM_VIDEO_MODULE_NAME).lexically_normal().string());
    }
  }
  candidates.emplace_back(TOFSIM_VIDEO_MODULE_PATH);
  for (const std::string& folder : splitFolders(TOFSIM_VIDEO_MODULE_INSTALLED_DIRS)) {
    candidates.push_back((std::filesystem::path(folder) / TOFSIM_VIDEO_MODULE_NAME).string());
  }
  return candidates;
}

// The first candidate that exists; the build tree's when none does (the
// error then names it).
std::string modulePath() {
  const std::vector<std::string> candidates = moduleCandidates();
  for (const std::string& c : candidates) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(c, ec)) return c;
  }
  return candidates.size() == 1 ? candidates.front() : std::string(TOFSIM_VIDEO_MODULE_PATH);
}

// Loaded once per process, never unloaded (OpenCV's backends keep threads).
const Module& module() {
  static std::once_flag once;
  static Module m;
  static std::string error;
  std::call_once(once, [] {
    const std::string path = modulePath();
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      error = "cannot load tofsim's video module " + path + ": " + (why ? why : "unknown") +
              " (TOFSIM_VIDEO_MODULE names another; it needs libopencv-videoio)";
      return;
    }
    m.open = reinterpret_cast<decltype(m.open)>(dlsym(handle, "tofsim_video_open"));
    m.write = reinterpret_cast<decltype(m.write)>(dlsym(handle, "tofsim_video_write"));
    m.close = reinterpret_cast<decltype(m.close)>(dlsym(handle, "tofsim_video_close"));
    if (!m.open || !m.write || !m.close) {
      error = "tofsim's video module " + path + " lacks its functions";
      m = Module{};
    }
  });
  if (!m.open) throw InputError(error);
  return m;
}

}  // namespace

void loadVideoModule() { module(); }

Mp4Writer::Mp4Writer(const std::filesystem::path& path, double fps, int width, int height)
    : width_(width), height_(height) {
  writer_ = module().open(path.c_str(), fps, width, height);
  if (writer_ == nullptr) {
    throw InputError(path.string() +
                     ": OpenCV cannot write MP4 (fourcc mp4v); is its FFmpeg "
                     "video I/O backend installed (libopencv-videoio)?");
  }
}

Mp4Writer::~Mp4Writer() { close(); }

void Mp4Writer::write(const unsigned char* bgr, std::size_t stride) {
  module().write(writer_, bgr, width_, height_, stride);
}

void Mp4Writer::close() {
  if (writer_ == nullptr) return;
  module().close(writer_);
  writer_ = nullptr;
}

}  // namespace tofsim::imaging::detail
