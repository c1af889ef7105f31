#include "tofsim/io/Npy.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {
namespace {

using test::TempDirTest;

std::string readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

/// A v1.0 file with an arbitrary dict, padded like NumPy pads it.
std::string npyWithDict(std::string dict, std::size_t dataBytes) {
  const std::size_t total = 10 + dict.size() + 1;
  dict.append((64 - total % 64) % 64, ' ');
  dict += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(dict.size() & 0xFF);
  out += static_cast<char>(dict.size() >> 8);
  return out + dict + std::string(dataBytes, '\0');
}

std::string errorOf(const std::filesystem::path& p) {
  try {
    readNpy(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

class NpyTest : public TempDirTest {};

TEST_F(NpyTest, RoundTripRanks1To4) {
  const std::vector<NpyShape> shapes{{7}, {3, 5}, {2, 3, 4}, {2, 3, 4, 3}};
  for (const NpyShape& shape : shapes) {
    std::vector<float> data(elementCount(shape));
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = 0.25f * float(i) - 3.0f;
    const auto path = dir_ / ("a" + std::to_string(shape.size()) + ".npy");
    writeNpy(path, shape, data.data());
    const NpyArray back = readNpy(path);
    EXPECT_EQ(back.shape, shape);
    EXPECT_EQ(back.data, data);
  }
}

TEST_F(NpyTest, HeaderBytesMatchSpec) {
  const std::vector<float> data(2 * 3 * 4 * 1, 1.0f);
  const auto path = dir_ / "h.npy";
  writeNpy(path, {2, 3, 4, 1}, data.data());
  const std::string bytes = readBytes(path);
  ASSERT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
  EXPECT_EQ(bytes[6], '\x01');
  EXPECT_EQ(bytes[7], '\x00');
  const std::size_t headerLen = uint8_t(bytes[8]) | uint8_t(bytes[9]) << 8;
  EXPECT_EQ((10 + headerLen) % 64, 0u);
  EXPECT_EQ(bytes.size(), 10 + headerLen + data.size() * 4);
  const std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3, 4, 1), }";
  // 10 preamble bytes + 65 dict bytes + padding + '\n' = 128.
  ASSERT_EQ(dict.size(), 65u);
  const std::string expected = dict + std::string(128 - 10 - 65 - 1, ' ') + "\n";
  EXPECT_EQ(headerLen, 118u);
  EXPECT_EQ(bytes.substr(10, headerLen), expected);
}

TEST_F(NpyTest, Rank1ShapeHasTrailingComma) {
  const float v[3] = {1, 2, 3};
  writeNpy(dir_ / "r1.npy", {3}, v);
  EXPECT_NE(readBytes(dir_ / "r1.npy").find("'shape': (3,), }"), std::string::npos);
}

TEST_F(NpyTest, VolumeAndImageOverloadsUseHWTCAndHWC) {
  TransientVolume volume(4, 2, TimeAxis{0.0, 1e-9, 6}, {"R", "G", "B"});
  volume.at(1, 3, 0, 2) = 5.0f;
  writeNpy(dir_ / "v.npy", volume);
  const NpyArray v = readNpy(dir_ / "v.npy");
  EXPECT_EQ(v.shape, (NpyShape{2, 4, std::size_t(volume.bins()), 3}));
  EXPECT_EQ(v.data, volume.values());

  Image image(5, 3, 2);
  image.at(2, 4, 1) = 7.0f;
  writeNpy(dir_ / "i.npy", image);
  const NpyArray i = readNpy(dir_ / "i.npy");
  EXPECT_EQ(i.shape, (NpyShape{3, 5, 2}));
  EXPECT_EQ(i.data, image.data);
}

TEST_F(NpyTest, ReaderAcceptsVersion2) {
  std::string bytes = npyWithDict("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }", 8);
  // Re-encode as v2.0: 4-byte header length.
  const std::string dict = bytes.substr(10, bytes.size() - 10 - 8);
  std::string v2 = "\x93NUMPY";
  v2 += '\x02';
  v2 += '\x00';
  const uint32_t n = static_cast<uint32_t>(dict.size());
  for (int i = 0; i < 4; ++i) v2 += static_cast<char>((n >> (8 * i)) & 0xFF);
  writeBytes(dir_ / "v2.npy", v2 + dict + std::string(8, '\0'));
  const NpyArray a = readNpy(dir_ / "v2.npy");
  EXPECT_EQ(a.shape, NpyShape{2});
  EXPECT_EQ(a.data, (std::vector<float>{0.0f, 0.0f}));
}

// The stream reader reads the same floats in pieces as readNpy at once, and
// checks the file's size before reading any.
TEST_F(NpyTest, StreamReaderReadsInPiecesWhatReadNpyReads) {
  std::vector<float> data(5 * 7 * 3);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = 0.25f * static_cast<float>(i) - 3.0f;
  const auto path = dir_ / "a.npy";
  io::writeNpy(path, {5, 7, 3}, data.data());
  io::NpyStreamReader reader(path);
  EXPECT_EQ(reader.shape(), (io::NpyShape{5, 7, 3}));
  std::vector<float> pieces;
  for (const std::size_t n : {1u, 20u, 0u, 64u, 20u}) {
    std::vector<float> piece(n);
    reader.read(piece.data(), n);
    pieces.insert(pieces.end(), piece.begin(), piece.end());
  }
  EXPECT_EQ(reader.remaining(), 0u);
  EXPECT_EQ(pieces, io::readNpy(path).data);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 4);
  EXPECT_THROW(io::NpyStreamReader{path}, InputError);
}

TEST_F(NpyTest, RejectsFloat64) {
  writeBytes(dir_ / "f8.npy", npyWithDict("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", 16));
  const std::string e = errorOf(dir_ / "f8.npy");
  EXPECT_NE(e.find("f8.npy"), std::string::npos) << e;
  EXPECT_NE(e.find("'<f8' is not supported"), std::string::npos) << e;
}

TEST_F(NpyTest, RejectsFortranOrder) {
  writeBytes(dir_ / "fo.npy", npyWithDict("{'descr': '<f4', 'fortran_order': True, 'shape': (2, 2), }", 16));
  const std::string e = errorOf(dir_ / "fo.npy");
  EXPECT_NE(e.find("fo.npy"), std::string::npos) << e;
  EXPECT_NE(e.find("fortran_order True"), std::string::npos) << e;
}

TEST_F(NpyTest, RejectsTruncatedData) {
  const std::vector<float> data(100, 2.0f);
  writeNpy(dir_ / "t.npy", {10, 10}, data.data());
  std::string bytes = readBytes(dir_ / "t.npy");
  writeBytes(dir_ / "t.npy", bytes.substr(0, bytes.size() - 6));
  const std::string e = errorOf(dir_ / "t.npy");
  EXPECT_NE(e.find("t.npy"), std::string::npos) << e;
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
}

TEST_F(NpyTest, HugeShapeInTinyFileIsAnErrorNotAnAllocation) {
  writeBytes(dir_ / "huge.npy",
             npyWithDict("{'descr': '<f4', 'fortran_order': False, 'shape': (100000, 100000, 1000), }", 4));
  EXPECT_NE(errorOf(dir_ / "huge.npy").find("huge.npy"), std::string::npos);
  writeBytes(dir_ / "ovf.npy",
             npyWithDict("{'descr': '<f4', 'fortran_order': False, 'shape': (99999999999, 99999999999), }", 4));
  EXPECT_NE(errorOf(dir_ / "ovf.npy").find("too large"), std::string::npos);
}

TEST_F(NpyTest, RejectsBadMagicAndTruncatedHeader) {
  writeBytes(dir_ / "m.npy", "PK\x03\x04 this is a zip file, not an npy file at all.....");
  const std::string e = errorOf(dir_ / "m.npy");
  EXPECT_NE(e.find("m.npy"), std::string::npos) << e;
  EXPECT_NE(e.find("bad magic"), std::string::npos) << e;
  writeBytes(dir_ / "short.npy", "\x93NUM");
  EXPECT_NE(errorOf(dir_ / "short.npy").find("bad magic"), std::string::npos);
  writeBytes(dir_ / "hdr.npy", npyWithDict("{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }", 0).substr(0, 30));
  EXPECT_NE(errorOf(dir_ / "hdr.npy").find("truncated header"), std::string::npos);
  EXPECT_NE(errorOf(dir_ / "missing.npy").find("missing.npy"), std::string::npos);
}

TEST_F(NpyTest, StreamWriterIsInvisibleUntilCommit) {
  const auto path = dir_ / "s.npy";
  const std::vector<float> row(4 * 3, 1.5f);
  NpyStreamWriter writer(path, {2, 4, 3});
  writer.append(row.data(), row.size());
  EXPECT_FALSE(std::filesystem::exists(path));
  writer.append(row.data(), row.size());
  EXPECT_FALSE(std::filesystem::exists(path));
  writer.commit();
  const NpyArray a = readNpy(path);
  EXPECT_EQ(a.shape, (NpyShape{2, 4, 3}));
  EXPECT_EQ(a.data, std::vector<float>(24, 1.5f));
  EXPECT_EQ(readBytes(path), [&] {
    std::vector<float> all(24, 1.5f);
    writeNpy(dir_ / "ref.npy", {2, 4, 3}, all.data());
    return readBytes(dir_ / "ref.npy");
  }());
}

TEST_F(NpyTest, StreamWriterRejectsTooFewAndTooMany) {
  const auto path = dir_ / "few.npy";
  const std::vector<float> data(10, 0.0f);
  {
    NpyStreamWriter writer(path, {2, 5});
    writer.append(data.data(), 7);
    EXPECT_THROW(writer.append(data.data(), 4), InputError);
    try {
      writer.commit();
      ADD_FAILURE() << "commit of an incomplete stream succeeded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("7 of 10"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_)) << "temporary left behind";
}

TEST_F(NpyTest, StreamWriterDestroyedWithoutCommitLeavesNoFile) {
  const std::vector<float> data(10, 0.0f);
  {
    NpyStreamWriter writer(dir_ / "abandoned.npy", {10});
    writer.append(data.data(), 10);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

}  // namespace
}  // namespace tofsim::io
