#pragma once
// Private to the config module: a CW-ToF sensor's `correlation:` (measured
// correlation waveforms), inline or read from files. One mapping (for every
// frequency) or a list of them (one per frequency), each with exactly one of
// `harmonics` (a list of [re, im]: c_1 .. c_K), `samples` (M values at
// phases 2 pi j / M) or `file` (a .csv of phase_rad,value rows, or a 1-D
// float32 .npy of M evenly spaced samples). Relative paths resolve against
// the config file's folder (ConfigPath.h); every bad value is an InputError
// located at the key, naming the file and its line.

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <vector>

#include "ConfigNode.h"
#include "tofsim/sensors/CwTofWaveform.h"

namespace tofsim::config {

/// `correlation` of the sensor node n, for `frequencies` modulation frequencies.
std::vector<sensors::CorrelationWaveform> parseCorrelation(const ConfigNode& n,
                                                           std::size_t frequencies);

/// Writes them back as parseCorrelation reads them (a file as its absolute path).
YAML::Node correlationToYaml(const std::vector<sensors::CorrelationWaveform>& waveforms);

}  // namespace tofsim::config
