// writeTalCapture: the 14 datasets of y-tal's layout, each with the dtype
// h5py gives the value tal render writes, built in memory and written through
// AtomicFile (a temporary renamed into place).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "Hdf5Handle.h"
#include "TalLayout.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

namespace {

using detail::h5Check;
using detail::H5Dataset;
using detail::H5File;
using detail::H5PropList;
using detail::H5Space;
using detail::H5Type;

// One chunk holds the whole time axis of a few neighbouring points,
// {T, 1, ..., 1, k}: reading one point's histogram H[:, i, j] (tal's
// per-point views, tofsim's comparisons) decompresses one chunk, not all of
// H. k = min(last axis, 16) neighbours give shuffle + deflate enough similar
// data to compress well. A chunk stays <= 1 MiB, h5py's default chunk cache:
// a bigger one cannot be cached and is decompressed again for every partial
// read; when T alone is larger, time is split too.
std::vector<hsize_t> chunkOfH(const std::vector<std::size_t>& shape) {
  constexpr std::size_t kMaxChunkValues = (std::size_t{1} << 20) / sizeof(float);
  std::vector<hsize_t> chunk(shape.size(), 1);
  const std::size_t t = shape.front();
  std::size_t k = std::min<std::size_t>(shape.back(), 16);
  k = std::clamp<std::size_t>(kMaxChunkValues / t, 1, k);
  chunk.back() = k;
  chunk.front() = std::min(t, kMaxChunkValues / k);
  return chunk;
}

class Writer {
 public:
  Writer(hid_t file, const std::filesystem::path& path) : file_(file), path_(path) {}

  void floats(const char* name, const std::vector<std::size_t>& shape, const float* data,
              hid_t dcpl = H5P_DEFAULT) {
    const std::vector<hsize_t> dims(shape.begin(), shape.end());
    const H5Space space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                              name, "cannot make its dataspace"));
    write(name, H5T_IEEE_F32LE, space.get(), H5T_NATIVE_FLOAT, data, dcpl);
  }

  /// H, chunked (chunkOfH) and compressed with shuffle + gzip 4: filters
  /// every HDF5 build and h5py read without plugins.
  void compressedFloats(const char* name, const std::vector<std::size_t>& shape,
                        const float* data) {
    const H5PropList dcpl(check(H5Pcreate(H5P_DATASET_CREATE), name, "cannot make its properties"));
    const std::vector<hsize_t> chunk = chunkOfH(shape);
    check(H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()), name,
          "cannot set its chunks");
    check(H5Pset_shuffle(dcpl.get()), name, "cannot add the shuffle filter");
    check(H5Pset_deflate(dcpl.get(), 4), name, "cannot add the deflate filter");
    floats(name, shape, data, dcpl.get());
  }

  void float64Scalar(const char* name, double value) {
    const H5Space space(check(H5Screate(H5S_SCALAR), name, "cannot make its dataspace"));
    write(name, H5T_IEEE_F64LE, space.get(), H5T_NATIVE_DOUBLE, &value);
  }

  /// As h5py.enum_dtype(members, basetype='i') with shape (1,): what tal
  /// writes for HFormat and GridFormat.
  template <std::size_t N>
  void enumInt32(const char* name, const std::array<std::pair<std::string_view, int>, N>& members,
                 int32_t value) {
    const H5Type type(check(H5Tenum_create(H5T_NATIVE_INT32), name, "cannot make its enum type"));
    for (const auto& [member, memberValue] : members) {
      const int32_t v = memberValue;
      check(H5Tenum_insert(type.get(), std::string(member).c_str(), &v), name,
            "cannot add an enum member");
    }
    const hsize_t one = 1;
    const H5Space space(
        check(H5Screate_simple(1, &one, nullptr), name, "cannot make its dataspace"));
    write(name, type.get(), space.get(), type.get(), &value);
  }

  /// A numpy bool as h5py stores it: a scalar enum {FALSE = 0, TRUE = 1} over
  /// int8 (h5py reads it back as np.bool_; a string would load as truthy bytes).
  void h5pyBool(const char* name, bool value) {
    const H5Type type(check(H5Tenum_create(H5T_NATIVE_INT8), name, "cannot make its enum type"));
    const int8_t no = 0, yes = 1;
    check(H5Tenum_insert(type.get(), "FALSE", &no), name, "cannot add an enum member");
    check(H5Tenum_insert(type.get(), "TRUE", &yes), name, "cannot add an enum member");
    const H5Space space(check(H5Screate(H5S_SCALAR), name, "cannot make its dataspace"));
    const int8_t v = value ? yes : no;
    write(name, type.get(), space.get(), type.get(), &v);
  }

  /// One variable-length UTF-8 string, scalar: what h5py writes for a str.
  void utf8String(const char* name, const std::string& text) {
    const H5Type type(check(H5Tcopy(H5T_C_S1), name, "cannot make its string type"));
    check(H5Tset_size(type.get(), H5T_VARIABLE), name, "cannot make its string type");
    check(H5Tset_cset(type.get(), H5T_CSET_UTF8), name, "cannot make its string type");
    const H5Space space(check(H5Screate(H5S_SCALAR), name, "cannot make its dataspace"));
    const char* cstr = text.c_str();
    write(name, type.get(), space.get(), type.get(), &cstr);
  }

 private:
  template <class T>
  T check(T status, const char* name, const char* what) const {
    return h5Check(status, path_, name, what);
  }

  void write(const char* name, hid_t fileType, hid_t space, hid_t memType, const void* data,
             hid_t dcpl = H5P_DEFAULT) {
    H5PropList own;
    if (dcpl == H5P_DEFAULT) {
      own = H5PropList(check(H5Pcreate(H5P_DATASET_CREATE), name, "cannot make its properties"));
      dcpl = own.get();
    }
    // Without the objects' modification times: the same capture gives the
    // same bytes (HDF5 stamps every dataset's header with the clock).
    check(H5Pset_obj_track_times(dcpl, 0), name, "cannot turn off its time stamps");
    const H5Dataset dataset(
        check(H5Dcreate2(file_, name, fileType, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), name,
              "cannot create the dataset"));
    check(H5Dwrite(dataset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name,
          "cannot write the dataset");
  }

  hid_t file_;
  const std::filesystem::path& path_;
};

void writeGrid(Writer& w, const TalGrid& grid, const std::string& prefix) {
  w.floats((prefix + "_grid_xyz").c_str(), grid.shape, grid.xyz.data());
  w.floats((prefix + "_grid_normals").c_str(), grid.shape, grid.normals.data());
  w.enumInt32((prefix + "_grid_format").c_str(), detail::kTalGridFormatMembers,
              static_cast<int32_t>(grid.format));
}

}  // namespace

void writeTalCapture(const std::filesystem::path& path, const TalCapture& capture) {
  detail::validateTalCapture(capture, path);
  // The temporary first: a missing directory fails before any compression.
  AtomicFile out(path);
  const detail::H5QuietErrors quiet;
  // HDF5 builds the file in memory (the core driver, no backing store) and
  // tofsim writes the image. On a file on disk, a failed write (disk full)
  // makes H5Fclose fail and leaves the file open inside HDF5 1.10, which then
  // crashes at exit trying to flush it again; in memory nothing can fail half
  // way, and AtomicFile turns a short write into an error, removing the
  // temporary. Costs one extra copy of the (compressed) file in memory.
  std::vector<unsigned char> image;
  {
    const H5PropList fapl(
        h5Check(H5Pcreate(H5P_FILE_ACCESS), path, "", "cannot make a file access list"));
    h5Check(H5Pset_fapl_core(fapl.get(), std::size_t{64} << 20, false), path, "",
            "cannot select HDF5's in-memory driver");
    const H5File file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()));
    if (!file.valid()) detail::throwH5(path, "", "cannot create the file in memory");
    Writer w(file.get(), path);
    w.compressedFloats("H", capture.H_shape, capture.H.data());
    w.enumInt32("H_format", detail::kTalHFormatMembers, static_cast<int32_t>(capture.H_format));
    w.floats("sensor_xyz", {3}, capture.sensor_xyz.data());
    w.floats("laser_xyz", {3}, capture.laser_xyz.data());
    writeGrid(w, capture.sensor_grid, "sensor");
    writeGrid(w, capture.laser_grid, "laser");
    w.float64Scalar("delta_t", capture.delta_t_m);
    w.float64Scalar("t_start", capture.t_start_m);
    w.h5pyBool("t_accounts_first_and_last_bounces", capture.t_accounts_first_and_last_bounces);
    w.utf8String("scene_info", capture.scene_info_yaml);
    // Flush first: H5Fget_file_image alone leaves metadata in HDF5's cache
    // out of the image (the file then fails to open: "bad object header").
    h5Check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), path, "", "cannot finish the file");
    const ssize_t size =
        h5Check(H5Fget_file_image(file.get(), nullptr, 0), path, "", "cannot finish the file");
    image.resize(static_cast<std::size_t>(size));
    h5Check(H5Fget_file_image(file.get(), image.data(), image.size()), path, "",
            "cannot finish the file");
  }
  out.write(image.data(), image.size());
  out.commit();
}

}  // namespace tofsim::io
