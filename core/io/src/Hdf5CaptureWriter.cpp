// H5CaptureWriter: float32 datasets chunked by captureChunk, shuffle +
// deflate, written into AtomicFile's temporary and renamed by commit().
#include <hdf5_hl.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Hdf5Attributes.h"
#include "Hdf5ChunkCodec.h"
#include "Hdf5Chunks.h"
#include "Hdf5Handle.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::io {

using detail::h5Check;
using detail::H5Dataset;
using detail::H5File;
using detail::H5PropList;
using detail::H5Space;

namespace {

using H5Group = detail::H5Handle<H5Gclose>;
constexpr unsigned kDeflateLevel = 4;

// Without the objects' modification times (HDF5 stamps each object header
// with the clock): the same calls give the same bytes.
H5PropList untimed(hid_t cls, const std::filesystem::path& path, const std::string& name) {
  H5PropList list(h5Check(H5Pcreate(cls), path, name, "cannot make its properties"));
  h5Check(H5Pset_obj_track_times(list.get(), 0), path, name, "cannot turn off its time stamps");
  return list;
}

}  // namespace

struct H5FloatStream::Impl {
  const std::filesystem::path* path = nullptr;
  std::string name;
  H5Dataset dataset;
  NpyShape shape;
  std::vector<hsize_t> chunk;    // captureChunk(shape)
  int threads = 0;               // compressing a block's chunks
  std::size_t inner = 1;         // values of one (row, column)
  std::size_t blockColumns = 1;  // columns of one block (the chunks' width)
  std::size_t nextPixel = 0;     // first pixel of the block being filled
  std::vector<float> block;      // its values so far

  // Values of the block that starts at nextPixel: to the end of its chunk
  // column or of its row.
  std::size_t blockValues() const {
    const std::size_t width = shape[1];
    const std::size_t column = nextPixel % width;
    const std::size_t end = std::min((column / blockColumns + 1) * blockColumns, width);
    return (end - column) * inner;
  }
};

H5FloatStream::H5FloatStream(std::unique_ptr<Impl> impl, std::size_t expected)
    : impl_(std::move(impl)), expected_(expected) {}

H5FloatStream::~H5FloatStream() = default;

void H5FloatStream::append(const float* data, std::size_t count) {
  Impl& s = *impl_;
  if (count > expected_ - appended_) {
    throw InputError(FileLoc{s.path->string()}, s.name,
                     "stream overflow: appending " + std::to_string(count) + " values after " +
                         std::to_string(appended_) + " of " + std::to_string(expected_));
  }
  while (count > 0) {
    const std::size_t take = std::min(count, s.blockValues() - s.block.size());
    s.block.insert(s.block.end(), data, data + take);
    data += take;
    count -= take;
    appended_ += take;
    if (s.block.size() == s.blockValues()) flushBlock();
  }
}

// The block is one row's run of whole chunk columns: ceil(T / chunk[2])
// chunks, each compressed on its own core and written as it is stored
// (H5Dwrite_chunk; an edge chunk padded with zeros, as HDF5 pads it).
void H5FloatStream::flushBlock() {
  Impl& s = *impl_;
  const detail::H5QuietErrors quiet;
  const std::filesystem::path& path = *s.path;
  std::vector<hsize_t> start(s.shape.size(), 0), count(s.shape.begin(), s.shape.end());
  start[0] = s.nextPixel / s.shape[1];
  start[1] = s.nextPixel % s.shape[1];
  count[0] = 1;
  count[1] = s.block.size() / s.inner;
  if (!s.chunk.empty()) {
    const std::size_t bins = s.shape[2], binsPerChunk = s.chunk[2];
    const std::size_t after = s.inner / bins;  // values of one (row, column, bin)
    std::vector<std::vector<unsigned char>> packed((bins + binsPerChunk - 1) / binsPerChunk);
    parallelFor(packed.size(), resolveThreads(s.threads), [&](std::size_t k) {
      std::vector<float> values(s.chunk[1] * binsPerChunk * after, 0.0f);
      const std::size_t t0 = k * binsPerChunk, t1 = std::min(bins, t0 + binsPerChunk);
      for (std::size_t c = 0; c < count[1]; ++c) {
        std::copy(s.block.begin() + static_cast<std::ptrdiff_t>((c * bins + t0) * after),
                  s.block.begin() + static_cast<std::ptrdiff_t>((c * bins + t1) * after),
                  values.begin() + static_cast<std::ptrdiff_t>(c * binsPerChunk * after));
      }
      packed[k] = detail::shuffleDeflate(values, kDeflateLevel);
    });
    for (std::size_t k = 0; k < packed.size(); ++k) {
      start[2] = k * binsPerChunk;
      h5Check(H5Dwrite_chunk(s.dataset.get(), H5P_DEFAULT, 0, start.data(), packed[k].size(),
                             packed[k].data()),
              path, s.name, "cannot write a chunk");
    }
    s.nextPixel += count[1];
    s.block.clear();
    return;
  }
  const H5Space file(h5Check(H5Dget_space(s.dataset.get()), path, s.name, "cannot read its shape"));
  h5Check(
      H5Sselect_hyperslab(file.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
      path, s.name, "cannot select a block");
  const hsize_t values = s.block.size();
  const H5Space memory(
      h5Check(H5Screate_simple(1, &values, nullptr), path, s.name, "cannot make a dataspace"));
  h5Check(H5Dwrite(s.dataset.get(), H5T_NATIVE_FLOAT, memory.get(), file.get(), H5P_DEFAULT,
                   s.block.data()),
          path, s.name, "cannot write a block");
  s.nextPixel += count[1];
  s.block.clear();
}

struct H5CaptureWriter::Impl {
  AtomicFile temporary;  // declared first: removed after the file is closed
  H5File file;
  std::deque<std::unique_ptr<H5FloatStream>> streams;
  std::filesystem::path path;
  int threads = 0;

  Impl(std::filesystem::path p, int t) : temporary(p), path(std::move(p)), threads(t) {}

  // The groups above `name` ("sensors/spad" of "sensors/spad/spad_counts").
  void makeParents(const std::string& name) {
    for (std::size_t slash = name.find('/'); slash != std::string::npos;
         slash = name.find('/', slash + 1)) {
      const std::string group = name.substr(0, slash);
      if (h5Check(H5Lexists(file.get(), group.c_str(), H5P_DEFAULT), path, group,
                  "cannot look the group up") > 0) {
        continue;
      }
      const H5PropList gcpl = untimed(H5P_GROUP_CREATE, path, group);
      const H5Group g(
          h5Check(H5Gcreate2(file.get(), group.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), path,
                  group, "cannot create the group"));
    }
  }

  H5Dataset create(const std::string& name, const NpyShape& shape) {
    makeParents(name);
    const std::vector<hsize_t> dims(shape.begin(), shape.end());
    const H5Space space(h5Check(
        dims.empty() ? H5Screate(H5S_SCALAR)
                     : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
        path, name, "cannot make its dataspace"));
    const H5PropList dcpl = untimed(H5P_DATASET_CREATE, path, name);
    const std::vector<hsize_t> chunk = detail::captureChunk(shape);
    if (!chunk.empty()) {
      h5Check(H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()), path, name,
              "cannot set its chunks");
      h5Check(H5Pset_shuffle(dcpl.get()), path, name, "cannot add the shuffle filter");
      h5Check(H5Pset_deflate(dcpl.get(), kDeflateLevel), path, name,
              "cannot add the deflate filter");
    }
    return H5Dataset(h5Check(H5Dcreate2(file.get(), name.c_str(), H5T_IEEE_F32LE, space.get(),
                                        H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                             path, name, "cannot create the dataset"));
  }
};

H5CaptureWriter::H5CaptureWriter(std::filesystem::path path, int threads)
    : impl_(std::make_unique<Impl>(std::move(path), threads)) {
  const detail::H5QuietErrors quiet;
  Impl& w = *impl_;
  // The root group's header too: without its time stamp.
  const H5PropList fcpl = untimed(H5P_FILE_CREATE, w.path, "");
  w.file =
      H5File(H5Fcreate(w.temporary.tempPath().c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT));
  if (!w.file.valid()) detail::throwH5(w.path, "", "cannot create the file");
}

H5CaptureWriter::~H5CaptureWriter() {
  if (!impl_) return;
  const detail::H5QuietErrors quiet;
  impl_->streams.clear();  // their datasets before the file
  impl_->file.close();
}

const std::filesystem::path& H5CaptureWriter::path() const { return impl_->path; }

H5FloatStream& H5CaptureWriter::stream(const std::string& name, const NpyShape& shape) {
  TOFSIM_CHECK_MSG(shape.size() >= 3, name);
  const detail::H5QuietErrors quiet;
  auto s = std::make_unique<H5FloatStream::Impl>();
  s->path = &impl_->path;
  s->name = name;
  s->shape = shape;
  s->threads = impl_->threads;
  for (std::size_t a = 2; a < shape.size(); ++a) s->inner *= shape[a];
  s->chunk = detail::captureChunk(shape);
  s->blockColumns = s->chunk.empty() ? shape[1] : s->chunk[1];
  s->dataset = impl_->create(name, shape);
  s->block.reserve(s->blockColumns * s->inner);
  const std::size_t expected = elementCount(shape);
  impl_->streams.push_back(
      std::unique_ptr<H5FloatStream>(new H5FloatStream(std::move(s), expected)));
  return *impl_->streams.back();
}

void H5CaptureWriter::write(const std::string& name, const NpyShape& shape, const float* data) {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset = impl_->create(name, shape);
  if (elementCount(shape) == 0) return;
  h5Check(H5Dwrite(dataset.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          impl_->path, name, "cannot write the dataset");
}

void H5CaptureWriter::setAttributes(const std::string& name,
                                    const std::vector<H5Attribute>& attributes) {
  const detail::H5QuietErrors quiet;
  const H5Dataset dataset(h5Check(H5Dopen2(impl_->file.get(), name.c_str(), H5P_DEFAULT),
                                  impl_->path, name, "cannot open the dataset"));
  for (const H5Attribute& a : attributes) {
    detail::writeAttribute(dataset.get(), a, impl_->path, name);
  }
}

void H5CaptureWriter::writeScale(const std::string& name, const std::vector<double>& values,
                                 const std::vector<H5Attribute>& attributes) {
  const detail::H5QuietErrors quiet;
  Impl& w = *impl_;
  w.makeParents(name);
  const hsize_t size = values.size();
  const H5Space space(
      h5Check(H5Screate_simple(1, &size, nullptr), w.path, name, "cannot make its dataspace"));
  const H5PropList dcpl = untimed(H5P_DATASET_CREATE, w.path, name);
  const H5Dataset dataset(h5Check(H5Dcreate2(w.file.get(), name.c_str(), H5T_IEEE_F64LE,
                                             space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                                  w.path, name, "cannot create the dataset"));
  if (!values.empty()) {
    h5Check(
        H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
        w.path, name, "cannot write the dataset");
  }
  const std::string base = name.substr(name.find_last_of('/') + 1);
  h5Check(H5DSset_scale(dataset.get(), base.c_str()), w.path, name,
          "cannot make it a dimension scale");
  for (const H5Attribute& a : attributes) detail::writeAttribute(dataset.get(), a, w.path, name);
}

void H5CaptureWriter::attachScale(const std::string& name, unsigned axis,
                                  const std::string& scale) {
  const detail::H5QuietErrors quiet;
  Impl& w = *impl_;
  const H5Dataset dataset(h5Check(H5Dopen2(w.file.get(), name.c_str(), H5P_DEFAULT), w.path, name,
                                  "cannot open the dataset"));
  const H5Dataset scaleSet(h5Check(H5Dopen2(w.file.get(), scale.c_str(), H5P_DEFAULT), w.path,
                                   scale, "cannot open the scale"));
  h5Check(H5DSattach_scale(dataset.get(), scaleSet.get(), axis), w.path, name,
          "cannot attach the scale " + scale);
  const std::string label = scale.substr(scale.find_last_of('/') + 1);
  h5Check(H5DSset_label(dataset.get(), axis, label.c_str()), w.path, name, "cannot label its axis");
}

void H5CaptureWriter::commit() {
  const detail::H5QuietErrors quiet;
  Impl& w = *impl_;
  for (const std::unique_ptr<H5FloatStream>& s : w.streams) {
    if (s->appended() != s->expected()) {
      throw InputError(FileLoc{w.path.string()}, s->impl_->name,
                       "stream incomplete: " + std::to_string(s->appended()) + " of " +
                           std::to_string(s->expected()) + " values appended; file not written");
    }
  }
  w.streams.clear();
  if (!w.file.close()) detail::throwH5(w.path, "", "cannot finish the file");
  w.temporary.commit();
}

}  // namespace tofsim::io
