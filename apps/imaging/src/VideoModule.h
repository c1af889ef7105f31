#pragma once
// Private to the imaging module: the MP4 encoder of video_module/, loaded on
// first use (dlopen), so that processes that write no video never load
// OpenCV's videoio and its ~240 libraries. It is looked for where the
// environment's TOFSIM_VIDEO_MODULE says, else beside an installed tofsim
// (<prefix>/lib/tofsim, found from the executable or the Python module), in
// the build tree, or under the install prefixes.

#include <filesystem>
#include <string>

namespace tofsim::imaging::detail {

/// Loads the module now (once per process); throws InputError when it cannot.
void loadVideoModule();

/// One MP4 file being written; RAII: the destructor closes it.
class Mp4Writer {
 public:
  /// Throws InputError naming the module when it cannot be loaded, or
  /// `path` when OpenCV cannot write MP4 there.
  Mp4Writer(const std::filesystem::path& path, double fps, int width, int height);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  /// One frame of the size given: rows of width BGR pixels, `stride` bytes apart.
  void write(const unsigned char* bgr, std::size_t stride);
  /// Finishes the file (the destructor does it otherwise).
  void close();

 private:
  void* writer_ = nullptr;
  int width_ = 0, height_ = 0;
};

}  // namespace tofsim::imaging::detail
