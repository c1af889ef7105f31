#pragma once
// Private to tofsim_io: what y-tal's layout is, shared by the writer and the
// reader (and the tests' expectations) so the two cannot drift: the field
// names, the enum members with their names, and the checks that a capture's
// shapes agree.

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tofsim/io/TalCapture.h"

namespace tofsim::io::detail {

/// Every top-level dataset, in the order written. tal.io.read_capture refuses
/// any other key, so the file holds these and nothing else.
inline constexpr std::array<std::string_view, 14> kTalFields{
    "H",
    "H_format",
    "sensor_xyz",
    "laser_xyz",
    "sensor_grid_xyz",
    "laser_grid_xyz",
    "sensor_grid_normals",
    "laser_grid_normals",
    "sensor_grid_format",
    "laser_grid_format",
    "delta_t",
    "t_start",
    "t_accounts_first_and_last_bounces",
    "scene_info",
};

/// Member names and values as tal/enums.py declares them; the names are what
/// h5py.enum_dtype stores in the file.
inline constexpr std::array<std::pair<std::string_view, int>, 5> kTalHFormatMembers{{
    {"UNKNOWN", 0},
    {"T_Sx_Sy", 1},
    {"T_Lx_Ly_Sx_Sy", 2},
    {"T_Si", 3},
    {"T_Li_Si", 4},
}};
inline constexpr std::array<std::pair<std::string_view, int>, 3> kTalGridFormatMembers{{
    {"UNKNOWN", 0},
    {"N_3", 1},
    {"X_Y_3", 2},
}};

std::size_t shapeProduct(const std::vector<std::size_t>& shape);
std::string shapeText(const std::vector<std::size_t>& shape);

/// Throws InputError(path, field, ...) unless every size agrees: H's rank
/// with H_format and H.size() with H_shape, each grid's shape with its format
/// and its xyz/normals sizes, H's point axes with the grids, delta_t > 0,
/// finite times, scene_info without NUL bytes.
void validateTalCapture(const TalCapture& capture, const std::filesystem::path& path);

}  // namespace tofsim::io::detail
