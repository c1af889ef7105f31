#pragma once
// The shape every fuzz target that reads a user's file through a config
// shares (fuzz_irf, fuzz_spad_tables, fuzz_camera_files): the configs name
// the shipped scenes, so workDir() gets a `scenes` link to configs/scenes
// once; each input is written as the file and its config (`write`, the
// target's *Input.h, shared with the regression test), loaded, and a config
// that loads is handed to `use`. InputError is the expected rejection.

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "FuzzFile.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::fuzz {

template <class Write, class Use>
int fuzzConfigFile(const uint8_t* data, std::size_t size, Write&& write, Use&& use) {
  static const bool linked = [] {
    std::filesystem::create_directory_symlink(TOFSIM_SOURCE_DIR "/configs/scenes",
                                              workDir() / "scenes");
    return true;
  }();
  (void)linked;
  const std::filesystem::path config = write(workDir(), data, size);
  if (config.empty()) return 0;
  try {
    use(config::loadRunConfig(config, {}));
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace tofsim::fuzz
