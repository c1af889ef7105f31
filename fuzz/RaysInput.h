#pragma once
// How fuzz_rays turns its bytes into a config that reads them as a ray list
// (rays: in place of camera:, apps/config RayFile.h), shared with the
// regression test (tests/hardening/FuzzRegressionTest.cpp) so both load an
// input alike. The first byte picks the format: even, a six-column CSV; odd,
// a .npy (N, 6). The rest is the file. `dir` holds a `scenes` link to
// configs/scenes.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace tofsim::fuzz {

/// Writes the ray file and its config into `dir`; returns the config's path,
/// or an empty path for an empty input.
inline std::filesystem::path writeRaysInput(const std::filesystem::path& dir, const uint8_t* data,
                                            std::size_t size) {
  if (size == 0) return {};
  const bool npy = (data[0] & 1u) != 0;
  const std::string file = npy ? "rays.npy" : "rays.csv";
  std::ofstream(dir / file, std::ios::binary)
      .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  const std::filesystem::path config = dir / "rays.yaml";
  std::ofstream(config) << "scene: scenes/cornell_box.gltf\n"
                           "rays: {file: "
                        << file
                        << "}\n"
                           "light: {type: point, position: [0.28, 0.5, 0.28]}\n"
                           "time: {start: 1.5 m, bin_width: 10 ps, bins: 64}\n";
  return config;
}

}  // namespace tofsim::fuzz
