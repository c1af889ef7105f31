#pragma once
// What an NLOS scan (config `nlos:`) will take before it starts, from the
// config alone (no scene): its files' bytes, for output.max_bytes and the
// free space, and its host memory, for render.memory_budget. H is held whole
// (time x the scan's points), so a grid of 4096 x 4096 points is gigabytes
// per time bin's worth of scan: refused in a second, naming the keys,
// instead of running out of memory or for an hour.

#include <cstdint>
#include <string>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/OutputEstimate.h"

namespace tofsim::pipeline {

/// H.npy and first_bounce.npy exactly (output.transient), capture.hdf5 at
/// most H's bytes (compressed), and each sensor's files.
OutputEstimate nlosOutputs(const config::RunConfig& config);

struct NlosMemory {
  std::uintmax_t bytes = 0;  ///< the most held at once
  std::string detail;        ///< its parts, with the keys that set them
};

/// H and first_bounce (float per bin per point), plus the larger of one
/// capture's collector (direct and indirect RGB per bin per gathered point:
/// every sensor point at once for single and exhaustive scans) and the
/// writers' working copy of H (capture.hdf5's, the sensors' input and
/// outputs).
NlosMemory nlosHostMemory(const config::RunConfig& config);

/// Throws InputError at the config file naming render.memory_budget and the
/// keys when nlosHostMemory is over it.
void checkNlosMemory(const config::RunConfig& config);

}  // namespace tofsim::pipeline
