#pragma once
// How fuzz_response_table turns its bytes into a measured scattering-delay
// kernel (issue 41's `scattering_delay: {model: table, file, delay_unit}`,
// apps/config/src/ResponseTableFile.cpp), shared with the regression test
// (tests/hardening/FuzzRegressionTest.cpp) so both load an input alike. The
// first byte picks the format (even: a two-column CSV; odd: an (n, 2) .npy)
// and, by (byte / 2) mod 5, the delay unit (s, ms, us, ns, ps). The rest is
// the file. A table that loads must give the temporal-response stage's taps
// on a 10 ps axis, or be refused there as too wide for it
// (std::invalid_argument, which the material table reports with its key).

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "apps/config/src/ConfigNode.h"
#include "apps/config/src/ResponseTableFile.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::fuzz {

/// Writes the table file and a materials YAML naming it into `dir`; returns
/// the YAML's path, or an empty path for an empty input.
inline std::filesystem::path writeResponseTableInput(const std::filesystem::path& dir,
                                                     const uint8_t* data, std::size_t size) {
  if (size == 0) return {};
  static constexpr const char* kUnits[] = {"s", "ms", "us", "ns", "ps"};
  const bool npy = (data[0] & 1u) != 0;
  const std::string file = npy ? "kernel.npy" : "kernel.csv";
  std::ofstream(dir / file, std::ios::binary)
      .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  const std::filesystem::path yaml = dir / "materials.yaml";
  std::ofstream(yaml) << "materials:\n  wax:\n    scattering_delay: {model: table, file: " << file
                      << ", delay_unit: " << kUnits[(data[0] / 2) % 5] << "}\n";
  return yaml;
}

/// Loads the table (InputError for a bad one) and lays it out on the stage.
inline void loadResponseTable(const std::filesystem::path& yaml) {
  const config::ConfigNode root(YAML::LoadFile(yaml.string()), yaml.string());
  physics::ResponseKernel kernel = config::parseResponseTable(
      root.child("materials").child("wax").child("scattering_delay"));
  kernel.fraction = 0.6;
  try {
    const physics::ResponseTaps taps = physics::responseTaps(kernel, 10e-12);
    double sum = taps.prompt;
    for (double t : taps.taps) sum += t;
    if (!(std::fabs(sum - 1.0) < 1e-6)) throw std::logic_error("a table's taps do not sum to 1");
  } catch (const std::invalid_argument&) {  // wider than the stage allows: the caller's error
  }
}

}  // namespace tofsim::fuzz
