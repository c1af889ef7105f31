#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {
namespace {

using test::TempDirTest;
using Hdf5CaptureTest = TempDirTest;

std::string readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// (H, W, T, C) with value = its C-order index.
std::vector<float> ramp(const NpyShape& shape) {
  std::vector<float> v(elementCount(shape));
  std::iota(v.begin(), v.end(), 0.0f);
  return v;
}

// Writes `values` of `shape` as "transient" in runs of `run` values.
void writeStreamed(const std::filesystem::path& file, const NpyShape& shape,
                   const std::vector<float>& values, std::size_t run, int threads = 0) {
  H5CaptureWriter writer(file, threads);
  H5FloatStream& s = writer.stream("transient", shape);
  for (std::size_t i = 0; i < values.size(); i += run) {
    s.append(values.data() + i, std::min(run, values.size() - i));
  }
  writer.setAttributes("transient", {{"json", std::string("{\"a\": 1}")},
                                     {"bin_width_s", 1e-11},
                                     {"bins", int64_t{70}},
                                     {"axes", std::vector<std::string>{"y", "x", "t", "c"}}});
  writer.commit();
}

bool hasTemporary(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
  }
  return false;
}

TEST_F(Hdf5CaptureTest, StreamedVolumeReadsBackWholeByPixelAndByBox) {
  const NpyShape shape{5, 7, 300, 3};  // time split into chunks of 128
  const std::vector<float> values = ramp(shape);
  const auto file = dir_ / "capture.h5";
  writeStreamed(file, shape, values, 3 * 300 * 3 + 17);  // runs that cut pixels and rows

  const H5CaptureReader reader(file);
  EXPECT_TRUE(reader.has("transient"));
  EXPECT_FALSE(reader.has("direct"));
  EXPECT_FALSE(reader.has("sensors/spad/spad_counts"));
  EXPECT_EQ(reader.shape("transient"), shape);
  EXPECT_EQ(reader.read("transient").data, values);

  // One pixel's histogram: (y, x) = (3, 5), all bins and channels.
  const std::vector<float> pixel = reader.readSlab("transient", {3, 5, 0, 0}, {1, 1, 300, 3});
  const std::size_t first = (3 * 7 + 5) * 300 * 3;
  EXPECT_EQ(pixel, std::vector<float>(values.begin() + first, values.begin() + first + 900));
  // One time slice: bin 200 of every pixel and channel.
  const std::vector<float> slice = reader.readSlab("transient", {0, 0, 200, 0}, {5, 7, 1, 3});
  ASSERT_EQ(slice.size(), 5u * 7 * 3);
  for (std::size_t p = 0; p < 35; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(slice[p * 3 + c], values[(p * 300 + 200) * 3 + c]);
    }
  }
  // A run of pixels across three rows (the end of one, a whole one, the start of one).
  std::vector<float> run(12 * 900);
  reader.readPixels("transient", 4, 12, run.data());
  EXPECT_EQ(run, std::vector<float>(values.begin() + 4 * 900, values.begin() + 16 * 900));
  EXPECT_EQ(reader.stringAttribute("transient", "json"), "{\"a\": 1}");
  EXPECT_EQ(reader.stringAttribute("transient", "units"), std::nullopt);
}

TEST_F(Hdf5CaptureTest, ChunkedWithShuffleAndDeflateAndNoTimeStamps) {
  const NpyShape shape{4, 6, 200, 3};
  const auto file = dir_ / "capture.h5";
  writeStreamed(file, shape, ramp(shape), 1000);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t d = H5Dopen2(f, "transient", H5P_DEFAULT);
  const hid_t dcpl = H5Dget_create_plist(d);
  hsize_t chunk[4] = {};
  ASSERT_EQ(H5Pget_chunk(dcpl, 4, chunk), 4);
  EXPECT_EQ(chunk[0], 1u);
  EXPECT_EQ(chunk[1], 6u);
  EXPECT_EQ(chunk[2], 128u);
  EXPECT_EQ(chunk[3], 3u);
  ASSERT_EQ(H5Pget_nfilters(dcpl), 2);
  unsigned flags = 0, values[8] = {};
  std::size_t n = 8;
  EXPECT_EQ(H5Pget_filter2(dcpl, 0, &flags, &n, values, 0, nullptr, nullptr), H5Z_FILTER_SHUFFLE);
  n = 8;
  EXPECT_EQ(H5Pget_filter2(dcpl, 1, &flags, &n, values, 0, nullptr, nullptr), H5Z_FILTER_DEFLATE);
  H5O_info_t info{};
  ASSERT_GE(H5Oget_info2(d, &info, H5O_INFO_TIME), 0);
  EXPECT_EQ(info.mtime, 0);  // no time stamp
  H5Pclose(dcpl);
  H5Dclose(d);
  H5Fclose(f);
  // The same calls, cut into other runs, compressed on 1 or 3 threads: the same bytes.
  writeStreamed(dir_ / "again.h5", shape, ramp(shape), 77, 1);
  EXPECT_EQ(readBytes(file), readBytes(dir_ / "again.h5"));
  writeStreamed(dir_ / "threads.h5", shape, ramp(shape), 5000, 3);
  EXPECT_EQ(readBytes(file), readBytes(dir_ / "threads.h5"));
  EXPECT_LT(std::filesystem::file_size(file), elementCount(shape) * sizeof(float));
}

TEST_F(Hdf5CaptureTest, WholeArraysInGroupsAnyRank) {
  const auto file = dir_ / "capture.h5";
  {
    H5CaptureWriter writer(file);
    const std::vector<float> depth = ramp({3, 4});
    writer.write("depth", {3, 4}, depth.data());
    const std::vector<float> counts = ramp({3, 4, 10});
    writer.write("sensors/spad/spad_counts", {3, 4, 10}, counts.data());
    const float scalar = 2.5f;
    writer.write("sensors/spad/scalar", {}, &scalar);
    writer.commit();
  }
  const H5CaptureReader reader(file);
  EXPECT_EQ(reader.read("depth").data, ramp({3, 4}));
  EXPECT_TRUE(reader.has("sensors/spad/spad_counts"));
  EXPECT_EQ(reader.read("sensors/spad/spad_counts").data, ramp({3, 4, 10}));
  EXPECT_EQ(reader.read("sensors/spad/scalar").data, std::vector<float>{2.5f});
}

TEST_F(Hdf5CaptureTest, FailedWriteLeavesTheEarlierFileIntact) {
  const NpyShape shape{3, 3, 20, 3};
  const auto file = dir_ / "capture.h5";
  writeStreamed(file, shape, ramp(shape), 100);
  const std::string before = readBytes(file);
  try {
    H5CaptureWriter writer(file);
    H5FloatStream& s = writer.stream("transient", shape);
    const std::vector<float> half(elementCount(shape) / 2, 7.0f);
    s.append(half.data(), half.size());
    throw std::runtime_error("a sink failed mid-write");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(readBytes(file), before);
  EXPECT_FALSE(hasTemporary(dir_));
  // An incomplete stream is refused at commit, naming file and dataset.
  try {
    H5CaptureWriter writer(file);
    writer.stream("direct", shape).append(ramp(shape).data(), 10);
    writer.commit();
    FAIL() << "commit of an incomplete stream";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("capture.h5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("direct"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readBytes(file), before);
  EXPECT_FALSE(hasTemporary(dir_));
}

TEST_F(Hdf5CaptureTest, DamagedFilesAreLocatedErrors) {
  const NpyShape shape{4, 4, 64, 3};
  const auto file = dir_ / "capture.h5";
  writeStreamed(file, shape, ramp(shape), 500);
  const std::string bytes = readBytes(file);
  const auto expectError = [&](const std::filesystem::path& p) {
    try {
      const H5CaptureReader reader(p);
      (void)reader.read("transient");
      FAIL() << p << " read without an error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(p.filename().string()), std::string::npos) << e.what();
    }
  };
  std::ofstream(dir_ / "truncated.h5", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expectError(dir_ / "truncated.h5");
  std::ofstream(dir_ / "text.h5", std::ios::binary) << "not an HDF5 file";
  expectError(dir_ / "text.h5");
  expectError(dir_ / "missing.h5");
}

// Another writer's chunks without filters (what libhdf5 1.10.8 trusts least:
// the reader counts their stored bytes) read back as they were written.
TEST_F(Hdf5CaptureTest, UnfilteredChunksOfAnotherWriterRead) {
  const NpyShape shape{4, 4, 8, 3};
  const std::vector<float> values = ramp(shape);
  const auto file = dir_ / "capture.h5";
  {
    const hid_t f = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t dims[4] = {4, 4, 8, 3}, chunk[4] = {1, 4, 8, 3};
    const hid_t space = H5Screate_simple(4, dims, nullptr);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(dcpl, 4, chunk);
    const hid_t d =
        H5Dcreate2(f, "transient", H5T_IEEE_F32LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    ASSERT_GE(H5Dwrite(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
    H5Dclose(d);
    H5Pclose(dcpl);
    H5Sclose(space);
    H5Fclose(f);
  }
  const H5CaptureReader reader(file);
  EXPECT_EQ(reader.shape("transient"), shape);
  EXPECT_EQ(reader.read("transient").data, values);
}

// A dataset's extent is a few bytes of the file: one that declares far more
// values than the file stores (here 2^28 rows of 4 x 8 x 3) must be refused
// by shape(), which callers allocate from, not allocated (96 GiB).
TEST_F(Hdf5CaptureTest, AnExtentBeyondTheStoredBytesIsALocatedError) {
  const NpyShape shape{4, 4, 8, 3};
  const auto file = dir_ / "capture.h5";
  writeStreamed(file, shape, ramp(shape), 100);
  std::string bytes = readBytes(file);
  // The dataspace message: the dims as little-endian uint64, then the max dims.
  const uint64_t dims[4] = {4, 4, 8, 3};
  const std::size_t at = bytes.find(std::string(reinterpret_cast<const char*>(dims), sizeof dims));
  ASSERT_NE(at, std::string::npos);
  const uint64_t rows = uint64_t{1} << 28;
  bytes.replace(at, sizeof rows, reinterpret_cast<const char*>(&rows), sizeof rows);
  std::ofstream(dir_ / "huge.h5", std::ios::binary) << bytes;
  const H5CaptureReader reader(dir_ / "huge.h5");
  try {
    (void)reader.shape("transient");
    FAIL() << "an extent of 2^28 rows read as a shape";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.h5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("transient"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("stored bytes"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)reader.read("transient"), InputError);
}

}  // namespace
}  // namespace tofsim::io
