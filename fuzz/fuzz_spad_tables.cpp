// Bytes -> a SPAD's table file (fuzz/SpadTablesInput.h): a TDC DNL (.csv or
// .npy) or a dark count map (.npy), read by config::loadRunConfig; a config
// that loads is run through the SPAD.
#include <filesystem>

#include "FuzzFile.h"
#include "SpadTablesInput.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool linked = [] {
    std::filesystem::create_directory_symlink(TOFSIM_SOURCE_DIR "/configs/scenes",
                                              tofsim::fuzz::workDir() / "scenes");
    return true;
  }();
  (void)linked;
  const auto config = tofsim::fuzz::writeSpadTablesInput(tofsim::fuzz::workDir(), data, size);
  if (config.empty()) return 0;
  try {
    tofsim::fuzz::runSpadTables(tofsim::config::loadRunConfig(config, {}));
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
