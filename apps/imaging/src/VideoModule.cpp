#include "VideoModule.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

#include "tofsim/util/Error.h"

namespace tofsim::imaging::detail {

namespace {

struct Module {
  void* (*open)(const char*, double, int, int) = nullptr;
  void (*write)(void*, const unsigned char*, int, int, unsigned long) = nullptr;
  void (*close)(void*) = nullptr;
};

std::string modulePath() {
  if (const char* p = std::getenv("TOFSIM_VIDEO_MODULE"); p != nullptr && *p != '\0') return p;
  return TOFSIM_VIDEO_MODULE_PATH;
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
