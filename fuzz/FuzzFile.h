#pragma once
// The loaders read files, so each fuzz input is written to a file in a
// private temporary folder first. InputError is the expected way to reject
// bad input; anything else escaping (another exception, a crash, a sanitizer
// report) is a bug that libFuzzer reports.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace tofsim::fuzz {

/// A folder for this fuzzing process, removed at exit.
inline const std::filesystem::path& workDir() {
  static const std::filesystem::path dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "tofsim_fuzz_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) std::abort();
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(workDir(), ec);
    });
    return std::filesystem::path(pattern);
  }();
  return dir;
}

#ifdef TOFSIM_SOURCE_DIR
/// Links the shipped configs/scenes into workDir() once, so that a config
/// written there with `scene: scenes/cornell_box.gltf` resolves as in configs/.
inline void linkShippedScenes() {
  static const bool linked = [] {
    std::filesystem::create_directory_symlink(TOFSIM_SOURCE_DIR "/configs/scenes",
                                              workDir() / "scenes");
    return true;
  }();
  (void)linked;
}
#endif

/// Writes the bytes to workDir()/name and returns the path.
inline std::filesystem::path writeInput(const std::string& name, const uint8_t* data, size_t size) {
  const std::filesystem::path path = workDir() / name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return path;
}

}  // namespace tofsim::fuzz
