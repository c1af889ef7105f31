#pragma once
// Sample captures for the TalCapture tests and the h5py check's sample
// writer: small, with every value distinct and non-trivial (negative,
// fractional, not representable in few bits), so a swapped axis or a lost
// field shows up in an exact comparison.

#include <cstddef>
#include <vector>

#include "tofsim/io/TalCapture.h"

namespace tofsim::io::test {

/// A wall grid (X_Y_3) at pixel centres of a 1 m x 0.8 m wall, z = 0, with
/// normals slightly tilted so that they are not all (0, 0, 1).
inline TalGrid sampleGrid(std::size_t nx, std::size_t ny, float offset) {
  TalGrid g;
  g.format = TalGridFormat::X_Y_3;
  g.shape = {nx, ny, 3};
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      g.xyz.insert(g.xyz.end(), {-0.5f + (i + 0.5f) / nx + offset, -0.4f + 0.8f * (j + 0.5f) / ny,
                                 0.001f * static_cast<float>(i * ny + j)});
      g.normals.insert(g.normals.end(), {0.01f * i, -0.02f * j, 0.999f});
    }
  }
  return g;
}

inline std::vector<float> sampleValues(std::size_t n) {
  std::vector<float> v(n);
  for (std::size_t k = 0; k < n; ++k) {
    v[k] = static_cast<float>(k % 97) * 1.0e-3f - 0.01f + static_cast<float>(k) * 3.0e-7f;
  }
  return v;
}

/// Confocal: H (T, Sx, Sy), T_Sx_Sy, laser grid == sensor grid.
inline TalCapture confocalSample() {
  TalCapture c;
  c.H_format = TalHFormat::T_Sx_Sy;
  c.H_shape = {40, 5, 4};
  c.H = sampleValues(40 * 5 * 4);
  c.sensor_grid = sampleGrid(5, 4, 0.0f);
  c.laser_grid = c.sensor_grid;
  c.sensor_xyz = {-0.5f, 0.0f, 0.25f};
  c.laser_xyz = {-0.25f, 0.125f, 0.75f};
  c.delta_t_m = 0.003;
  c.t_start_m = -0.0125;
  c.t_accounts_first_and_last_bounces = false;
  c.scene_info_yaml = "tofsim_version: 0.1.0\nseed: 7\nconfig: {scan: confocal}\nnote: \"µm ok\"\n";
  return c;
}

/// Exhaustive: H (T, Lx, Ly, Sx, Sy), T_Lx_Ly_Sx_Sy, laser grid 2 x 3,
/// sensor grid 4 x 5 (Sy > 1 and not a multiple of the chunk's 16).
inline TalCapture exhaustiveSample() {
  TalCapture c;
  c.H_format = TalHFormat::T_Lx_Ly_Sx_Sy;
  c.H_shape = {17, 2, 3, 4, 5};
  c.H = sampleValues(17 * 2 * 3 * 4 * 5);
  c.sensor_grid = sampleGrid(4, 5, 0.0f);
  c.laser_grid = sampleGrid(2, 3, 0.03125f);
  c.sensor_xyz = {0.5f, -0.1f, 0.3f};
  c.laser_xyz = {-0.5f, 0.2f, 0.4f};
  c.delta_t_m = 0.0015;
  c.t_start_m = 0.6;
  c.t_accounts_first_and_last_bounces = true;
  c.scene_info_yaml = "tofsim_version: 0.1.0\nseed: 11\n";
  return c;
}

}  // namespace tofsim::io::test
