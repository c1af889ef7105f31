// readTalCapture: y-tal's layout back into a TalCapture. Lenient in what
// HDF5 can convert (float64 or int64 arrays, enums or plain ints, scalars or
// (1,)) as tal render's files differ from ours there; strict in what cannot
// mean the same (a missing field, a string where a number belongs, shapes
// that disagree). Unknown extra keys (tal's empty volume_format) are ignored.
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "Hdf5Extent.h"
#include "Hdf5Handle.h"
#include "TalLayout.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

namespace {

using detail::H5Dataset;
using detail::H5File;
using detail::H5Space;
using detail::H5Type;

class Reader {
 public:
  Reader(hid_t file, const std::filesystem::path& path) : file_(file), path_(path) {}

  /// Any integer or float array, converted to float32 by HDF5.
  std::vector<float> floats(const std::string& name, std::vector<std::size_t>& shape) const {
    const Field f = open(name);
    const H5T_class_t cls = H5Tget_class(f.type.get());
    require(cls == H5T_FLOAT || cls == H5T_INTEGER, name, "must be numeric");
    shape = f.shape;
    std::vector<float> values(f.count);
    check(H5Dread(f.dataset.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          name, "cannot read the dataset");
    return values;
  }

  std::array<float, 3> float3(const std::string& name) const {
    std::vector<std::size_t> shape;
    const std::vector<float> v = floats(name, shape);
    require(shape == std::vector<std::size_t>{3}, name,
            "must have shape (3,), got " + detail::shapeText(shape));
    return {v[0], v[1], v[2]};
  }

  double float64Scalar(const std::string& name) const {
    const Field f = open(name);
    const H5T_class_t cls = H5Tget_class(f.type.get());
    require(cls == H5T_FLOAT || cls == H5T_INTEGER, name, "must be a number");
    require(f.count == 1, name, "must be one value, got shape " + detail::shapeText(f.shape));
    double value = 0;
    check(H5Dread(f.dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value), name,
          "cannot read the dataset");
    return value;
  }

  /// One integer stored as an HDF5 enum (h5py.enum_dtype, h5py's bool) or a
  /// plain integer (older tal files): the value, whatever the member names.
  int64_t integer(const std::string& name) const {
    const Field f = open(name);
    require(f.count == 1, name, "must be one value, got shape " + detail::shapeText(f.shape));
    const H5T_class_t cls = H5Tget_class(f.type.get());
    int64_t value = 0;
    if (cls == H5T_INTEGER) {
      check(H5Dread(f.dataset.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value), name,
            "cannot read the dataset");
      return value;
    }
    require(cls == H5T_ENUM, name, "must be an enum or an integer");
    // HDF5 converts enums only to enums (by member name), so read the stored
    // integer in the enum's own native layout, then convert that as an integer.
    const H5Type memType(
        check(H5Tget_native_type(f.type.get(), H5T_DIR_ASCEND), name, "cannot read its enum type"));
    const H5Type base(check(H5Tget_super(memType.get()), name, "cannot read its enum type"));
    require(H5Tget_size(base.get()) <= sizeof(int64_t), name,
            "has an enum base wider than 64 bits");
    alignas(int64_t) unsigned char buffer[sizeof(int64_t)] = {};
    check(H5Dread(f.dataset.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer), name,
          "cannot read the dataset");
    check(H5Tconvert(base.get(), H5T_NATIVE_INT64, 1, buffer, nullptr, H5P_DEFAULT), name,
          "cannot convert its enum value");
    std::memcpy(&value, buffer, sizeof value);
    return value;
  }

  int32_t enumValue(const std::string& name, int32_t lastValue) const {
    const int64_t v = integer(name);
    require(
        v >= 0 && v <= lastValue, name,
        "value " + std::to_string(v) + " is not a member (0.." + std::to_string(lastValue) + ")");
    return static_cast<int32_t>(v);
  }

  bool boolean(const std::string& name) const {
    const int64_t v = integer(name);
    require(v == 0 || v == 1, name, "must be a bool, got " + std::to_string(v));
    return v == 1;
  }

  /// A scalar string, variable-length (h5py's str) or fixed-length.
  std::string string(const std::string& name) const {
    const Field f = open(name);
    require(H5Tget_class(f.type.get()) == H5T_STRING, name, "must be a string");
    require(f.count == 1, name, "must be one string, got shape " + detail::shapeText(f.shape));
    const H5Type memType(check(H5Tcopy(H5T_C_S1), name, "cannot make a string type"));
    check(H5Tset_cset(memType.get(), H5Tget_cset(f.type.get())), name, "cannot make a string type");
    if (H5Tis_variable_str(f.type.get()) > 0) {
      check(H5Tset_size(memType.get(), H5T_VARIABLE), name, "cannot make a string type");
      char* text = nullptr;
      check(H5Dread(f.dataset.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &text), name,
            "cannot read the dataset");
      std::string out = text ? text : "";
      const H5Space space(H5Dget_space(f.dataset.get()));
#if H5_VERSION_GE(1, 12, 0)
      H5Treclaim(memType.get(), space.get(), H5P_DEFAULT, &text);
#else
      H5Dvlen_reclaim(memType.get(), space.get(), H5P_DEFAULT, &text);
#endif
      return out;
    }
    const std::size_t size = H5Tget_size(f.type.get());
    check(H5Tset_size(memType.get(), size + 1), name, "cannot make a string type");
    std::string out(size + 1, '\0');
    check(H5Dread(f.dataset.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), name,
          "cannot read the dataset");
    out.resize(out.find('\0'));
    return out;
  }

  void require(bool ok, const std::string& field, const std::string& message) const {
    if (!ok) throw InputError(FileLoc{path_.string()}, field, message);
  }

 private:
  struct Field {
    H5Dataset dataset;
    H5Type type;
    std::vector<std::size_t> shape;  // {} for a scalar
    std::size_t count = 0;
  };

  Field open(const std::string& name) const {
    require(H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0, name, "missing field");
    Field f;
    f.dataset = H5Dataset(
        check(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), name, "is not a dataset (a group?)"));
    f.type = H5Type(check(H5Dget_type(f.dataset.get()), name, "cannot read its type"));
    const H5Space space(check(H5Dget_space(f.dataset.get()), name, "cannot read its dataspace"));
    require(H5Sget_simple_extent_type(space.get()) != H5S_NULL, name, "is empty (no data)");
    detail::H5Extent extent = detail::checkedExtent(f.dataset.get(), path_, name);
    f.shape = std::move(extent.shape);
    f.count = extent.count;
    return f;
  }
  template <class T>
  T check(T status, const std::string& field, const std::string& what) const {
    return detail::h5Check(status, path_, field, what);
  }

  hid_t file_;
  const std::filesystem::path& path_;
};

TalGrid readGrid(const Reader& r, const std::string& prefix) {
  TalGrid grid;
  grid.format = static_cast<TalGridFormat>(r.enumValue(prefix + "_grid_format", 2));
  grid.xyz = r.floats(prefix + "_grid_xyz", grid.shape);
  std::vector<std::size_t> normalsShape;
  grid.normals = r.floats(prefix + "_grid_normals", normalsShape);
  r.require(normalsShape == grid.shape, prefix + "_grid_normals",
            "shape " + detail::shapeText(normalsShape) + " differs from " + prefix +
                "_grid_xyz's " + detail::shapeText(grid.shape));
  return grid;
}

}  // namespace

TalCapture readTalCapture(const std::filesystem::path& path) {
  const detail::H5QuietErrors quiet;
  // H5Fopen on a missing file reports only "unable to open file"; say why.
  if (!std::filesystem::exists(path)) {
    throw InputError(FileLoc{path.string()}, "", "no such file");
  }
  const H5File file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) detail::throwH5(path, "", "cannot open as HDF5");
  const Reader r(file.get(), path);
  TalCapture c;
  c.H_format = static_cast<TalHFormat>(r.enumValue("H_format", 4));
  c.H = r.floats("H", c.H_shape);
  c.sensor_xyz = r.float3("sensor_xyz");
  c.laser_xyz = r.float3("laser_xyz");
  c.sensor_grid = readGrid(r, "sensor");
  c.laser_grid = readGrid(r, "laser");
  c.delta_t_m = r.float64Scalar("delta_t");
  c.t_start_m = r.float64Scalar("t_start");
  c.t_accounts_first_and_last_bounces = r.boolean("t_accounts_first_and_last_bounces");
  c.scene_info_yaml = r.string("scene_info");
  detail::validateTalCapture(c, path);
  return c;
}

}  // namespace tofsim::io
