// H5CaptureReader: datasets of a capture.h5 read whole, as a box, or as a
// run of pixels (a union of at most three boxes: the end of a row, whole
// rows, the start of a row).
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "Hdf5Attributes.h"
#include "Hdf5Extent.h"
#include "Hdf5Handle.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

using detail::h5Check;
using detail::H5Dataset;
using detail::H5File;
using detail::H5PropList;
using detail::H5Space;
using detail::H5Type;

namespace {
// A run of pixels touches a row of chunks at a time; 32 MiB holds the
// chunks of one row of a wide volume, so each is decompressed once.
constexpr std::size_t kChunkCacheBytes = std::size_t{32} << 20;
}  // namespace

struct H5CaptureReader::Impl {
  std::filesystem::path path;
  H5File file;

  H5Dataset open(const std::string& name) const {
    const H5PropList dapl(
        h5Check(H5Pcreate(H5P_DATASET_ACCESS), path, name, "cannot make its properties"));
    h5Check(H5Pset_chunk_cache(dapl.get(), 12421, kChunkCacheBytes, 1.0), path, name,
            "cannot size its chunk cache");
    H5Dataset dataset(H5Dopen2(file.get(), name.c_str(), dapl.get()));
    if (!dataset.valid()) detail::throwH5(path, name, "no such dataset");
    const H5Type type(h5Check(H5Dget_type(dataset.get()), path, name, "cannot read its type"));
    if (H5Tget_class(type.get()) != H5T_FLOAT) detail::throwH5(path, name, "not a float dataset");
    return dataset;
  }

  // Checked against the file (Hdf5Extent.h): callers allocate from it.
  NpyShape shapeOf(hid_t dataset, const std::string& name) const {
    return detail::checkedExtent(dataset, path, name).shape;
  }

  // Reads the file's selection `file` of `dataset` into `values` floats.
  void read(hid_t dataset, hid_t fileSpace, std::size_t values, float* out,
            const std::string& name) const {
    if (values == 0) return;
    const hsize_t n = values;
    const H5Space memory(
        h5Check(H5Screate_simple(1, &n, nullptr), path, name, "cannot make a dataspace"));
    h5Check(H5Dread(dataset, H5T_NATIVE_FLOAT, memory.get(), fileSpace, H5P_DEFAULT, out), path,
            name, "cannot read the dataset (damaged or truncated file?)");
  }
};

H5CaptureReader::H5CaptureReader(std::filesystem::path path) : impl_(std::make_unique<Impl>()) {
  impl_->path = std::move(path);
  const detail::H5QuietErrors quiet;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(impl_->path, ec)) {
    throw InputError(FileLoc{impl_->path.string()}, "", "not found");
  }
  impl_->file = H5File(H5Fopen(impl_->path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!impl_->file.valid()) {
    detail::throwH5(impl_->path, "", "cannot open as HDF5 (not an HDF5 file, or damaged)");
  }
}

H5CaptureReader::~H5CaptureReader() = default;

const std::filesystem::path& H5CaptureReader::path() const { return impl_->path; }

bool H5CaptureReader::has(const std::string& name) const {
  const detail::H5QuietErrors quiet;
  // Each level of the path exists (H5Lexists fails on a missing parent).
  for (std::size_t slash = name.find('/');; slash = name.find('/', slash + 1)) {
    const std::string part = name.substr(0, slash);
    if (H5Lexists(impl_->file.get(), part.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) break;
  }
  return H5Oexists_by_name(impl_->file.get(), name.c_str(), H5P_DEFAULT) > 0;
}

NpyShape H5CaptureReader::shape(const std::string& name) const {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset = impl_->open(name);
  return impl_->shapeOf(dataset.get(), name);
}

NpyArray H5CaptureReader::read(const std::string& name) const {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset = impl_->open(name);
  NpyArray array;
  array.shape = impl_->shapeOf(dataset.get(), name);
  array.data.resize(elementCount(array.shape));
  const H5Space file(
      h5Check(H5Dget_space(dataset.get()), impl_->path, name, "cannot read its shape"));
  impl_->read(dataset.get(), file.get(), array.data.size(), array.data.data(), name);
  return array;
}

std::vector<float> H5CaptureReader::readSlab(const std::string& name, const NpyShape& start,
                                             const NpyShape& count) const {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset = impl_->open(name);
  const NpyShape shape = impl_->shapeOf(dataset.get(), name);
  bool inside = start.size() == shape.size() && count.size() == shape.size();
  for (std::size_t a = 0; inside && a < shape.size(); ++a) {
    inside = start[a] <= shape[a] && count[a] <= shape[a] - start[a];
  }
  if (!inside) throw InputError(FileLoc{impl_->path.string()}, name, "box outside the dataset");
  const std::vector<hsize_t> s(start.begin(), start.end()), c(count.begin(), count.end());
  const H5Space file(
      h5Check(H5Dget_space(dataset.get()), impl_->path, name, "cannot read its shape"));
  std::vector<float> values(elementCount(count));
  if (values.empty()) return values;
  h5Check(H5Sselect_hyperslab(file.get(), H5S_SELECT_SET, s.data(), nullptr, c.data(), nullptr),
          impl_->path, name, "cannot select the box");
  impl_->read(dataset.get(), file.get(), values.size(), values.data(), name);
  return values;
}

void H5CaptureReader::readPixels(const std::string& name, std::size_t firstPixel,
                                 std::size_t pixels, float* out) const {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset = impl_->open(name);
  const NpyShape shape = impl_->shapeOf(dataset.get(), name);
  TOFSIM_CHECK_MSG(shape.size() >= 2, name);
  const std::size_t width = shape[1];
  TOFSIM_CHECK(firstPixel + pixels <= shape[0] * width);
  std::size_t inner = 1;
  for (std::size_t a = 2; a < shape.size(); ++a) inner *= shape[a];
  if (pixels == 0) return;
  const H5Space file(
      h5Check(H5Dget_space(dataset.get()), impl_->path, name, "cannot read its shape"));
  std::vector<hsize_t> start(shape.size(), 0), count(shape.begin(), shape.end());
  H5S_seloper_t op = H5S_SELECT_SET;
  const auto select = [&](std::size_t row, std::size_t column, std::size_t rows,
                          std::size_t columns) {
    start[0] = row;
    start[1] = column;
    count[0] = rows;
    count[1] = columns;
    h5Check(H5Sselect_hyperslab(file.get(), op, start.data(), nullptr, count.data(), nullptr),
            impl_->path, name, "cannot select pixels");
    op = H5S_SELECT_OR;
  };
  std::size_t pixel = firstPixel, left = pixels;
  if (pixel % width != 0 || left < width) {  // the rest of a row
    const std::size_t n = std::min(left, width - pixel % width);
    select(pixel / width, pixel % width, 1, n);
    pixel += n;
    left -= n;
  }
  if (left >= width) {  // whole rows
    select(pixel / width, 0, left / width, width);
    pixel += left / width * width;
    left %= width;
  }
  if (left > 0) select(pixel / width, 0, 1, left);  // the start of a row
  impl_->read(dataset.get(), file.get(), pixels * inner, out, name);
}

std::optional<std::string> H5CaptureReader::stringAttribute(const std::string& name,
                                                            const std::string& attribute) const {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset = impl_->open(name);
  return detail::readStringAttribute(dataset.get(), attribute, impl_->path, name);
}

}  // namespace tofsim::io
