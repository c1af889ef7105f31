// Bytes -> a SPAD's measured instrument response file (irf: in a config,
// fuzz/IrfInput.h), read by config::loadRunConfig: a CSV or a .npy.
#include <filesystem>

#include "FuzzFile.h"
#include "IrfInput.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool linked = [] {
    std::filesystem::create_directory_symlink(TOFSIM_SOURCE_DIR "/configs/scenes",
                                              tofsim::fuzz::workDir() / "scenes");
    return true;
  }();
  (void)linked;
  const auto config = tofsim::fuzz::writeIrfInput(tofsim::fuzz::workDir(), data, size);
  if (config.empty()) return 0;
  try {
    tofsim::config::loadRunConfig(config, {});
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
