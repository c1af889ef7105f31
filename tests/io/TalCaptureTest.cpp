// writeTalCapture / readTalCapture: round trips, the checks before writing,
// atomic replacement, and read errors that name the field.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/TalCaptureSamples.h"
#include "support/TempDir.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {
namespace {

using test::confocalSample;
using test::exhaustiveSample;

class TalCaptureTest : public tofsim::test::TempDirTest {
 protected:
  std::vector<std::string> filesInDir() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) {
      names.push_back(e.path().filename().string());
    }
    return names;
  }
};

void expectGridEq(const TalGrid& a, const TalGrid& b) {
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.shape, b.shape);
  EXPECT_EQ(a.xyz, b.xyz);
  EXPECT_EQ(a.normals, b.normals);
}

// Every field, exactly: float32 and float64 survive HDF5 bit for bit.
void expectCaptureEq(const TalCapture& a, const TalCapture& b) {
  EXPECT_EQ(a.H_shape, b.H_shape);
  EXPECT_EQ(a.H, b.H);
  EXPECT_EQ(a.H_format, b.H_format);
  EXPECT_EQ(a.sensor_xyz, b.sensor_xyz);
  EXPECT_EQ(a.laser_xyz, b.laser_xyz);
  expectGridEq(a.sensor_grid, b.sensor_grid);
  expectGridEq(a.laser_grid, b.laser_grid);
  EXPECT_EQ(a.delta_t_m, b.delta_t_m);
  EXPECT_EQ(a.t_start_m, b.t_start_m);
  EXPECT_EQ(a.t_accounts_first_and_last_bounces, b.t_accounts_first_and_last_bounces);
  EXPECT_EQ(a.scene_info_yaml, b.scene_info_yaml);
}

/// The InputError's key (the field) and message of a write, or "" if none.
template <class F>
InputError errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("none");
}

TEST_F(TalCaptureTest, ConfocalRoundTripIsExact) {
  const TalCapture c = confocalSample();
  writeTalCapture(dir_ / "confocal.hdf5", c);
  expectCaptureEq(readTalCapture(dir_ / "confocal.hdf5"), c);
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"confocal.hdf5"});
}

std::string bytesOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The same capture written a second later has the same bytes: HDF5 would
// stamp each dataset with its modification time (1 s resolution) unless told
// not to.
TEST_F(TalCaptureTest, TheSameCaptureWrittenLaterHasTheSameBytes) {
  const TalCapture c = confocalSample();
  writeTalCapture(dir_ / "first.hdf5", c);
  ::usleep(1'100'000);
  writeTalCapture(dir_ / "second.hdf5", c);
  EXPECT_TRUE(bytesOf(dir_ / "first.hdf5") == bytesOf(dir_ / "second.hdf5"));
}

TEST_F(TalCaptureTest, ExhaustiveRoundTripIsExact) {
  const TalCapture c = exhaustiveSample();
  writeTalCapture(dir_ / "exhaustive.hdf5", c);
  expectCaptureEq(readTalCapture(dir_ / "exhaustive.hdf5"), c);
}

TEST_F(TalCaptureTest, PointListFormatsRoundTrip) {
  TalCapture c = confocalSample();
  c.H_format = TalHFormat::T_Si;
  c.H_shape = {40, 20};
  for (TalGrid* g : {&c.sensor_grid, &c.laser_grid}) {
    g->format = TalGridFormat::N_3;
    g->shape = {20, 3};
  }
  writeTalCapture(dir_ / "n3.hdf5", c);
  expectCaptureEq(readTalCapture(dir_ / "n3.hdf5"), c);
}

// A long time axis: the chunk must still fit (<= 1 MiB) and read back whole.
TEST_F(TalCaptureTest, LongTimeAxisRoundTrips) {
  TalCapture c = confocalSample();
  c.H_shape = {300000, 5, 4};
  c.H = test::sampleValues(300000 * 5 * 4);
  writeTalCapture(dir_ / "long.hdf5", c);
  EXPECT_EQ(readTalCapture(dir_ / "long.hdf5").H, c.H);
}

TEST_F(TalCaptureTest, SizeMismatchesNameTheField) {
  struct Case {
    const char* field;
    void (*spoil)(TalCapture&);
  };
  const Case cases[] = {
      {"H", [](TalCapture& c) { c.H.pop_back(); }},
      {"H",
       [](TalCapture& c) {
         c.H_shape = {40, 20};
       }},
      {"H",
       [](TalCapture& c) {
         c.H_shape = {0, 5, 4};
       }},
      {"H_format", [](TalCapture& c) { c.H_format = TalHFormat::Unknown; }},
      {"sensor_grid_xyz", [](TalCapture& c) { c.sensor_grid.xyz.push_back(1); }},
      {"sensor_grid_xyz",
       [](TalCapture& c) {
         c.sensor_grid.shape = {5, 4, 2};
       }},
      {"sensor_grid_normals", [](TalCapture& c) { c.sensor_grid.normals.pop_back(); }},
      {"laser_grid_normals", [](TalCapture& c) { c.laser_grid.normals.clear(); }},
      {"laser_grid_format", [](TalCapture& c) { c.laser_grid.format = TalGridFormat::Unknown; }},
      // H's (Sx, Sy) = (5, 4), the sensor grid 4 x 5: same size, wrong shape.
      {"sensor_grid_xyz", [](TalCapture& c) { c.sensor_grid = test::sampleGrid(4, 5, 0); }},
      {"delta_t", [](TalCapture& c) { c.delta_t_m = 0; }},
      {"scene_info", [](TalCapture& c) { c.scene_info_yaml += '\0'; }},
  };
  for (const Case& k : cases) {
    TalCapture c = confocalSample();
    k.spoil(c);
    const InputError e = errorOf([&] { writeTalCapture(dir_ / "bad.hdf5", c); });
    EXPECT_EQ(e.key(), k.field) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.hdf5"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(filesInDir().empty());
}

TEST_F(TalCaptureTest, ExhaustiveLaserAxesMustMatchTheLaserGrid) {
  TalCapture c = exhaustiveSample();
  c.laser_grid = test::sampleGrid(3, 2, 0);
  EXPECT_EQ(errorOf([&] { writeTalCapture(dir_ / "bad.hdf5", c); }).key(), "laser_grid_xyz");
}

TEST_F(TalCaptureTest, WriteIntoMissingDirectoryThrowsAndLeavesNothing) {
  const auto path = dir_ / "missing" / "c.hdf5";
  const InputError e = errorOf([&] { writeTalCapture(path, confocalSample()); });
  EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  EXPECT_FALSE(std::filesystem::exists(dir_ / "missing"));
  EXPECT_TRUE(filesInDir().empty());
}

TEST_F(TalCaptureTest, FailedWriteLeavesTheOldFileIntact) {
  const auto path = dir_ / "c.hdf5";
  writeTalCapture(path, confocalSample());
  TalCapture bad = exhaustiveSample();
  bad.H.resize(3);
  EXPECT_THROW(writeTalCapture(path, bad), InputError);
  expectCaptureEq(readTalCapture(path), confocalSample());
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"c.hdf5"});
}

// The temporary cannot be created (its name is taken by a directory): the
// old file stays, and the directory, not ours, is not removed.
TEST_F(TalCaptureTest, UncreatableTemporaryLeavesTheOldFile) {
  const auto path = dir_ / "c.hdf5";
  writeTalCapture(path, confocalSample());
  auto blocker = path;
  blocker += ".tmp-" + std::to_string(::getpid());
  std::filesystem::create_directory(blocker);
  EXPECT_THROW(writeTalCapture(path, exhaustiveSample()), InputError);
  EXPECT_TRUE(std::filesystem::is_directory(blocker));
  std::filesystem::remove(blocker);
  expectCaptureEq(readTalCapture(path), confocalSample());
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"c.hdf5"});
}

// A write that fails half-way (the file-size limit stands in for a full
// disk: write() fails with EFBIG): the old file stays, no temporary is left.
TEST_F(TalCaptureTest, WriteFailingHalfWayLeavesTheOldFileAndNoTemporary) {
  const auto path = dir_ / "c.hdf5";
  writeTalCapture(path, confocalSample());
  TalCapture big = confocalSample();
  big.H_shape = {200000, 5, 4};
  big.H.resize(200000 * 5 * 4);
  unsigned state = 12345;  // noise, so that deflate cannot shrink it below the limit
  for (float& v : big.H) v = static_cast<float>((state = state * 1664525u + 1013904223u) >> 8);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 1 << 20;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const InputError e = errorOf([&] { writeTalCapture(path, big); });
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  expectCaptureEq(readTalCapture(path), confocalSample());
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"c.hdf5"});
}

TEST_F(TalCaptureTest, ReplacesAnExistingFile) {
  const auto path = dir_ / "c.hdf5";
  writeTalCapture(path, confocalSample());
  writeTalCapture(path, exhaustiveSample());
  expectCaptureEq(readTalCapture(path), exhaustiveSample());
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"c.hdf5"});
}

// Every field removed in turn (with the C API): the error names it and the path.
TEST_F(TalCaptureTest, MissingFieldIsNamed) {
  const auto path = dir_ / "c.hdf5";
  const char* fields[] = {"H",
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
                          "scene_info"};
  for (const char* field : fields) {
    writeTalCapture(path, confocalSample());
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Ldelete(file, field, H5P_DEFAULT), 0);
    H5Fclose(file);
    const InputError e = errorOf([&] { readTalCapture(path); });
    EXPECT_EQ(e.key(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find("missing field"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST_F(TalCaptureTest, MissingOrNonHdf5FileThrowsWithThePath) {
  EXPECT_THROW(readTalCapture(dir_ / "none.hdf5"), InputError);
  std::ofstream(dir_ / "text.hdf5") << "not hdf5";
  const InputError e = errorOf([&] { readTalCapture(dir_ / "text.hdf5"); });
  EXPECT_NE(std::string(e.what()).find("text.hdf5"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace tofsim::io
