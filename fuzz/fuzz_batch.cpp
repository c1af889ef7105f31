// Bytes -> batch YAML next to a tiny run config and the shipped scenes ->
// config::loadBatchConfig, then the first runs and the last of its lazy
// expansion, each run's config loaded (fuzz/BatchInput.h).
#include <filesystem>

#include "BatchInput.h"
#include "FuzzFile.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tofsim::fuzz::linkShippedScenes();
  const auto path = tofsim::fuzz::writeBatchInput(tofsim::fuzz::workDir(), data, size);
  try {
    tofsim::fuzz::runBatchInput(tofsim::config::loadBatchConfig(path, {}));
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
