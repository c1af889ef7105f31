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

/// One light component both renders wrote (direct, indirect, bounce<k>).
struct ComponentComparison {
  std::string name;
  compare::VolumeComparison comparison;
};

struct CompareSummary {
  compare::VolumeComparison comparison;  ///< of transient.npy
  /// The components found in both A and B, in the order direct, indirect,
  /// bounce1, bounce2, ...
  std::vector<ComponentComparison> components;
  std::vector<std::string> files;  ///< written, relative to the output directory
};

/// Writes compare_energy.csv, compare_energy.png, compare_arrival.exr and
/// compare_arrival.png into `outputDirectory` (created when missing), and
/// compare_components.csv when A and B share a component.
CompareSummary runCompare(const std::filesystem::path& a, const std::filesystem::path& b,
                          const std::filesystem::path& outputDirectory);

/// The components' lines of the printed summary ("" when there are none).
std::string componentsTable(const std::vector<ComponentComparison>& components);

}  // namespace tofsim::pipeline
