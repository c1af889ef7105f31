#pragma once
// Synthetic volumes for the sensor tests.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors::test {

inline TransientVolume makeVolume(int32_t w, int32_t h, double start_s, double binWidth_s,
                                  int32_t bins, int32_t channels = 1) {
  TimeAxis axis;
  axis.start_s = start_s;
  axis.bin_width_s = binWidth_s;
  axis.bins = bins;
  std::vector<std::string> names;
  for (int32_t c = 0; c < channels; ++c) names.push_back("c" + std::to_string(c));
  return TransientVolume(w, h, axis, names);
}

inline const SensorOutput& output(const std::vector<SensorOutput>& outs, const std::string& name,
                                  SensorOutput::Kind kind = SensorOutput::Kind::Image) {
  const SensorOutput* o = findOutput(outs, name, kind);
  if (!o) throw std::runtime_error("missing output " + name);
  return *o;
}

inline const SensorOutput& array(const std::vector<SensorOutput>& outs, const std::string& name) {
  return output(outs, name, SensorOutput::Kind::Array);
}

}  // namespace tofsim::sensors::test
