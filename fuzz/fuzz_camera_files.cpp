// Bytes -> a camera's file (fuzz/CameraFilesInput.h): an OpenCV lens
// calibration, a CW-ToF correlation waveform (.csv or .npy) or a vignetting
// map, read by config::loadRunConfig; a config that loads has its pixel rays
// traced and is run through the CW-ToF sensor.
#include <filesystem>

#include "CameraFilesInput.h"
#include "FuzzFile.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool linked = [] {
    std::filesystem::create_directory_symlink(TOFSIM_SOURCE_DIR "/configs/scenes",
                                              tofsim::fuzz::workDir() / "scenes");
    return true;
  }();
  (void)linked;
  const auto config = tofsim::fuzz::writeCameraFilesInput(tofsim::fuzz::workDir(), data, size);
  if (config.empty()) return 0;
  try {
    tofsim::fuzz::runCameraFiles(tofsim::config::loadRunConfig(config, {}));
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
