#pragma once
// NLOS relay-wall captures in y-tal's HDF5 layout (FileFormat.HDF5_TAL), the
// files `tal render` writes and `tal.io.read_capture` (y-tal 0.20.0) reads:
// exactly 14 top-level datasets, nothing else (the reader refuses any other
// key). Field by field (dtype, shape, meaning): shared/research/
// nlos-capture-format.md, section 1. Lengths are metres of optical path (OPL).

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tofsim::io {

/// tal.enums.HFormat: what each axis of H is (T = time, always axis 0).
enum class TalHFormat : int32_t {
  Unknown = 0,
  T_Sx_Sy = 1,
  T_Lx_Ly_Sx_Sy = 2,
  T_Si = 3,
  T_Li_Si = 4
};
/// tal.enums.GridFormat: the shape of a grid of wall points.
enum class TalGridFormat : int32_t { Unknown = 0, N_3 = 1, X_Y_3 = 2 };

/// Points on the relay wall (metres, wall frame: the wall is z = 0, normal +z).
struct TalGrid {
  TalGridFormat format = TalGridFormat::X_Y_3;
  std::vector<std::size_t> shape;  // {X, Y, 3} or {N, 3}
  std::vector<float> xyz;          // row-major in `shape`
  std::vector<float> normals;      // same shape
};

struct TalCapture {
  std::vector<std::size_t> H_shape;  // {T, Sx, Sy} or {T, Lx, Ly, Sx, Sy} (or T_Si / T_Li_Si)
  std::vector<float> H;              // row-major in H_shape (time slowest)
  TalHFormat H_format = TalHFormat::T_Sx_Sy;
  std::array<float, 3> sensor_xyz{}, laser_xyz{};  // device origins (metres), not wall points
  TalGrid sensor_grid, laser_grid;
  double delta_t_m = 0.0;  // bin width, metres of optical path
  double t_start_m = 0.0;  // OPL of bin 0's leading edge
  bool t_accounts_first_and_last_bounces = false;
  std::string scene_info_yaml;  // tofsim's version, config, seed
};

/// Writes atomically: to a temporary file beside `path`, then renamed over it,
/// so a failure (disk full, a signal) leaves no half-written file. Throws
/// tofsim's InputError (tofsim/util/Error.h: bad input or environment) with the
/// path on failure; checks that shapes and sizes agree first (InputError naming
/// the field, before any file is created).
void writeTalCapture(const std::filesystem::path& path, const TalCapture& capture);

/// Reads a file in this layout (also files written by y-tal's `tal render`:
/// normals stored int64, enums as enum or plain int, an extra empty
/// `volume_format`); throws InputError with the path and the field on a
/// missing or malformed field, or shapes that disagree (the writer's checks).
TalCapture readTalCapture(const std::filesystem::path& path);

}  // namespace tofsim::io
