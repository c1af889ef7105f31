// Bytes -> a camera's file (fuzz/CameraFilesInput.h): an OpenCV lens
// calibration, a CW-ToF correlation waveform (.csv or .npy) or a vignetting
// map, read by config::loadRunConfig; a config that loads has its pixel rays
// traced and is run through the CW-ToF sensor.
#include "CameraFilesInput.h"
#include "ConfigFileInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return tofsim::fuzz::fuzzConfigFile(data, size, tofsim::fuzz::writeCameraFilesInput,
                                      tofsim::fuzz::runCameraFiles);
}
