#include "TalLayout.h"

#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::io::detail {

std::size_t shapeProduct(const std::vector<std::size_t>& shape) {
  std::size_t n = 1;
  for (const std::size_t d : shape) n *= d;
  return n;
}

std::string shapeText(const std::vector<std::size_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    s += (i ? ", " : "") + std::to_string(shape[i]);
  }
  return s + (shape.size() == 1 ? ",)" : ")");
}

namespace {

class Checker {
 public:
  explicit Checker(const std::filesystem::path& path) : path_(path) {}
  void require(bool ok, const std::string& field, const std::string& message) const {
    if (!ok) throw InputError(FileLoc{path_.string()}, field, message);
  }

 private:
  const std::filesystem::path& path_;
};

void checkGrid(const Checker& check, const TalGrid& grid, const std::string& prefix) {
  const std::string xyz = prefix + "_grid_xyz";
  check.require(grid.format == TalGridFormat::X_Y_3 || grid.format == TalGridFormat::N_3,
                prefix + "_grid_format", "must be X_Y_3 or N_3");
  const std::size_t rank = grid.format == TalGridFormat::X_Y_3 ? 3 : 2;
  check.require(grid.shape.size() == rank && grid.shape.back() == 3, xyz,
                "shape " + shapeText(grid.shape) + " does not match its format (" +
                    (rank == 3 ? "X, Y, 3" : "N, 3") + ")");
  const std::size_t count = shapeProduct(grid.shape);
  check.require(count > 0, xyz, "shape " + shapeText(grid.shape) + " is empty");
  check.require(grid.xyz.size() == count, xyz,
                "has " + std::to_string(grid.xyz.size()) + " values, shape " +
                    shapeText(grid.shape) + " needs " + std::to_string(count));
  check.require(grid.normals.size() == count, prefix + "_grid_normals",
                "has " + std::to_string(grid.normals.size()) + " values, shape " +
                    shapeText(grid.shape) + " needs " + std::to_string(count));
}

// H's point axes after T (e.g. Lx, Ly of T_Lx_Ly_Sx_Sy) against one grid.
void checkPointAxes(const Checker& check, const TalCapture& c, std::size_t first, std::size_t count,
                    const TalGrid& grid, const std::string& prefix) {
  const TalGridFormat want = count == 2 ? TalGridFormat::X_Y_3 : TalGridFormat::N_3;
  check.require(grid.format == want, prefix + "_grid_format",
                std::string("must be ") + (count == 2 ? "X_Y_3" : "N_3") + " for this H_format");
  for (std::size_t i = 0; i < count; ++i) {
    check.require(
        c.H_shape[first + i] == grid.shape[i], prefix + "_grid_xyz",
        "shape " + shapeText(grid.shape) + " does not match H's shape " + shapeText(c.H_shape));
  }
}

}  // namespace

void validateTalCapture(const TalCapture& c, const std::filesystem::path& path) {
  const Checker check(path);
  std::size_t rank = 0;
  switch (c.H_format) {
    case TalHFormat::T_Sx_Sy:
      rank = 3;
      break;
    case TalHFormat::T_Lx_Ly_Sx_Sy:
      rank = 5;
      break;
    case TalHFormat::T_Si:
      rank = 2;
      break;
    case TalHFormat::T_Li_Si:
      rank = 3;
      break;
    default:
      check.require(false, "H_format", "must be one of T_Sx_Sy, T_Lx_Ly_Sx_Sy, T_Si, T_Li_Si");
  }
  check.require(c.H_shape.size() == rank, "H",
                "shape " + shapeText(c.H_shape) + " has rank " + std::to_string(c.H_shape.size()) +
                    ", H_format needs " + std::to_string(rank));
  const std::size_t count = shapeProduct(c.H_shape);
  check.require(count > 0, "H", "shape " + shapeText(c.H_shape) + " is empty");
  check.require(c.H.size() == count, "H",
                "has " + std::to_string(c.H.size()) + " values, shape " + shapeText(c.H_shape) +
                    " needs " + std::to_string(count));
  checkGrid(check, c.sensor_grid, "sensor");
  checkGrid(check, c.laser_grid, "laser");
  switch (c.H_format) {
    case TalHFormat::T_Sx_Sy:
      checkPointAxes(check, c, 1, 2, c.sensor_grid, "sensor");
      break;
    case TalHFormat::T_Si:
      checkPointAxes(check, c, 1, 1, c.sensor_grid, "sensor");
      break;
    case TalHFormat::T_Lx_Ly_Sx_Sy:
      checkPointAxes(check, c, 1, 2, c.laser_grid, "laser");
      checkPointAxes(check, c, 3, 2, c.sensor_grid, "sensor");
      break;
    case TalHFormat::T_Li_Si:
      checkPointAxes(check, c, 1, 1, c.laser_grid, "laser");
      checkPointAxes(check, c, 2, 1, c.sensor_grid, "sensor");
      break;
    default:
      break;
  }
  check.require(std::isfinite(c.delta_t_m) && c.delta_t_m > 0, "delta_t",
                "must be finite and > 0 (got " + std::to_string(c.delta_t_m) + ")");
  check.require(std::isfinite(c.t_start_m), "t_start", "must be finite");
  // A C string in the file: a NUL would silently cut the YAML short.
  check.require(c.scene_info_yaml.find('\0') == std::string::npos, "scene_info",
                "contains a NUL byte");
}

}  // namespace tofsim::io::detail
