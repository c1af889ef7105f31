// Bytes -> a SPAD's measured instrument response file (irf: in a config,
// fuzz/IrfInput.h), read by config::loadRunConfig: a CSV or a .npy.
#include "ConfigFileInput.h"
#include "IrfInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return tofsim::fuzz::fuzzConfigFile(data, size, tofsim::fuzz::writeIrfInput,
                                      [](const tofsim::config::RunConfig&) {});
}
