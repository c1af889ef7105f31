// Bytes -> a material's measured scattering-delay kernel (issue 41's
// `scattering_delay: {model: table}`, fuzz/ResponseTableInput.h): a CSV or
// an (n, 2) .npy read by config::parseResponseTable, then laid out as the
// temporal-response stage's taps. InputError is the expected rejection.
#include <filesystem>

#include "FuzzFile.h"
#include "ResponseTableInput.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path yaml =
      tofsim::fuzz::writeResponseTableInput(tofsim::fuzz::workDir(), data, size);
  if (yaml.empty()) return 0;
  try {
    tofsim::fuzz::loadResponseTable(yaml);
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
