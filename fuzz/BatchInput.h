#pragma once
// How fuzz_batch turns its bytes into a batch file, shared with the
// regression test (tests/hardening/FuzzRegressionTest.cpp) so both load an
// input alike: the bytes are the batch YAML, written as `batch.yaml` next to
// a tiny run config, `tiny.yaml` (4 x 4 pixels of the shipped Cornell box,
// through `dir`'s `scenes` link), which the seeds name as `base`. A batch
// that loads has its first runs and its last made (the lazy sweep's
// enumeration, BatchExpansion.cpp) and their configs loaded, as `tofsim
// batch` validates them; a run whose name is not a plain folder name is a
// bug (abort), a config that does not load an InputError.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tofsim/config/BatchConfig.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::fuzz {

/// Writes tiny.yaml and the bytes as batch.yaml into `dir`; returns the
/// batch file's path.
inline std::filesystem::path writeBatchInput(const std::filesystem::path& dir, const uint8_t* data,
                                             std::size_t size) {
  std::ofstream(dir / "tiny.yaml") << "scene: scenes/cornell_box.gltf\n"
                                      "camera: {gltf_camera: cornell_camera, resolution: [4, 4]}\n"
                                      "light: {type: point, position: [0.28, 0.5, 0.28]}\n"
                                      "time: {start: 1.5 m, bin_width: 10 ps, bins: 16}\n"
                                      "sensors: []\n";
  const std::filesystem::path batch = dir / "batch.yaml";
  std::ofstream(batch, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return batch;
}

/// Run `index` made and its config loaded; the name checked as the folder
/// name it becomes.
inline void loadBatchRun(const config::BatchConfig& batch, std::size_t index) {
  const config::BatchRun run = batch.run(index);
  const std::string& name = run.name;
  if (run.index != index || name.empty() || name.size() > config::kMaxRunName ||
      name[0] == '.' || name.find('/') != std::string::npos) {
    std::abort();
  }
  try {
    config::loadRunConfig(batch.base_config, run.overrides);
  } catch (const InputError&) {  // a run's bad value: validateBatch's rejection
  }
}

/// The first three runs and the last (a sweep of up to kMaxBatchRuns is made
/// on demand, never as a list).
inline void runBatchInput(const config::BatchConfig& batch) {
  const std::size_t runs = batch.runCount();
  if (runs == 0 || runs > config::kMaxBatchRuns) std::abort();
  for (std::size_t i = 0; i < runs && i < 3; ++i) loadBatchRun(batch, i);
  if (runs > 3) loadBatchRun(batch, runs - 1);
}

}  // namespace tofsim::fuzz
