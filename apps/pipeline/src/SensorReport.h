#pragma once
// Private to the pipeline: what a run says about its sensors, the same for
// camera renders (SensorStreams) and NLOS captures (NlosSensors).

#include <cstddef>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

/// The sensor library does not know the config: `e` again, naming the
/// config file and the entry sensors[i].
[[noreturn]] void rethrowSensorError(const config::RunConfig& config, std::size_t i,
                                     const InputError& e);

/// Each warning on stderr, even when quiet: they say the outputs mislead
/// (they go into the metadata too, SensorMetadata.h).
void printSensorWarnings(const sensors::SensorSpec& spec, const std::vector<std::string>& warnings);

}  // namespace tofsim::pipeline
