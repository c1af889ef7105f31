#pragma once
// `tofsim compare A B`: error metrics of the render in A against the
// reference in B (both output directories of `tofsim render`), written as a
// table, an energy-over-time CSV and plot, and a per-pixel map of the
// earliest-arrival difference.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/compare/VolumeComparison.h"

namespace tofsim::pipeline {

struct CompareSummary {
  compare::VolumeComparison comparison;
  std::vector<std::string> files;  ///< written, relative to the output directory
};

/// Writes compare_energy.csv, compare_energy.png, compare_arrival.exr and
/// compare_arrival.png into `outputDirectory` (created when missing).
CompareSummary runCompare(const std::filesystem::path& a, const std::filesystem::path& b,
                          const std::filesystem::path& outputDirectory);

}  // namespace tofsim::pipeline
