#pragma once
// How fuzz_spad_tables turns its bytes into a config whose SPAD reads them as
// a table file (apps/config/src/SpadTableFile.cpp), shared with the
// regression test (tests/hardening/FuzzRegressionTest.cpp) so both load an
// input alike. The first byte picks the table, by its value mod 5: 0, a TDC
// DNL as a one-column CSV (`tdc_dnl: dnl.csv`); 1, the same as a 1-D .npy;
// 2, a dark count map as a 2-D .npy (`dark_count_map: dcr.npy`); 3, an
// afterpulse delay density as a two-column CSV (`afterpulse_delay_table:
// afterpulse.csv`, with afterpulses on); 4, the same as an (n, 2) .npy. The
// rest is the file. The config is small enough that a table that loads can
// fit it (8 TDC bins: 8 DNL values summing to 0; a 4 x 4 image: a 4 x 4 map),
// so the fuzzer also reaches the sensor, which runSpadTables then runs (a
// delay table on the exact event engine). `dir` holds a `scenes` link to
// configs/scenes.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "tofsim/config/RunConfig.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::fuzz {

/// Writes the table file and its config into `dir`; returns the config's
/// path, or an empty path for an empty input.
inline std::filesystem::path writeSpadTablesInput(const std::filesystem::path& dir,
                                                  const uint8_t* data, std::size_t size) {
  if (size == 0) return {};
  static constexpr const char* kFiles[] = {"dnl.csv", "dnl.npy", "dcr.npy", "afterpulse.csv",
                                           "afterpulse.npy"};
  static constexpr const char* kKeys[] = {"tdc_dnl", "tdc_dnl", "dark_count_map",
                                          "afterpulse_delay_table", "afterpulse_delay_table"};
  const int kind = data[0] % 5;
  const std::string file = kFiles[kind];
  std::ofstream(dir / file, std::ios::binary)
      .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  const std::filesystem::path config = dir / "spad_tables.yaml";
  std::ofstream(config) << "scene: scenes/cornell_box.gltf\n"
                           "camera: {gltf_camera: cornell_camera, resolution: [4, 4]}\n"
                           "light: {type: point, position: [0.28, 0.5, 0.28]}\n"
                           "time: {start: 1.5 m, bin_width: 10 ps, bins: 8}\n"
                           "sensors:\n"
                           "  - type: spad\n"
                           "    cycles: 100\n"
                           "    ambient_rate: 1 GHz\n"
                        << (kind >= 3 ? "    afterpulse_probability: 0.2\n" : "") << "    "
                        << kKeys[kind] << ": " << file << "\n";
  return config;
}

/// Runs the loaded config's SPAD on a lit volume of its image and time axis:
/// a table the config accepts must be one the sensor can use.
inline void runSpadTables(const config::RunConfig& run) {
  const auto& spad = std::get<sensors::SpadParams>(run.sensors.at(0).params);
  const capture::Camera& camera = run.camera.camera;
  TransientVolume volume(camera.width, camera.height, run.render.time, {"r", "g", "b"});
  for (std::size_t i = 0; i < volume.size(); ++i) volume.data()[i] = 0.01f * (i % 7);
  sensors::runSpad(volume, spad, 1);
}

}  // namespace tofsim::fuzz
