#pragma once
// Every config key, declared once: path, type, range, default, unit and a
// one-line doc. The key tables of configs/README.md and sensors/README.md are
// checked against these lists by a test (ConfigKeysTest), as are the keys the
// effective-config writer emits and the loader accepts. The rows of sensor
// parameters and of render.indirect / render.reference are made from their
// field tables (sensors/SensorFields.h, apps/config/src/RunFields.h).

#include <span>

namespace tofsim::config {

struct ConfigKey {
  const char* path;          ///< "time.bin_width"; sensor keys: "<model|common|bins>.<key>"
  const char* type;          ///< string, bool, int, number, duration, angle, vec3, mapping, ...
  const char* range;         ///< "in [1, 2^20]", "> 0", or "" when any value of the type is valid
  const char* defaultValue;  ///< as written in a config, or "required"
  const char* unit;          ///< of a bare number; "-" when none
  const char* doc;           ///< one line
};

/// Keys of a run config (the `sensors:` entries are in sensorConfigKeys).
std::span<const ConfigKey> runConfigKeys();
/// Keys of one `sensors:` entry: "common.*" every model, "bins.*" the
/// instrument bins of streak and SPAD, "<type>.*" one model's.
std::span<const ConfigKey> sensorConfigKeys();

}  // namespace tofsim::config
