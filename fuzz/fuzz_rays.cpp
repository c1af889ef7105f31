// Bytes -> a ray list's file (rays: in a config, fuzz/RaysInput.h), read by
// config::loadRunConfig: a CSV or a .npy, float32 or float64.
#include "ConfigFileInput.h"
#include "RaysInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return tofsim::fuzz::fuzzConfigFile(data, size, tofsim::fuzz::writeRaysInput,
                                      [](const tofsim::config::RunConfig&) {});
}
