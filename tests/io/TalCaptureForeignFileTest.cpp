// readTalCapture on files tofsim did not write: what tal render's files do
// differently (int64 normals, plain-int enums, an empty volume_format) reads
// back; what tal.io.read_capture would misread (a string flag, scene_info as
// a group) is an error naming the field. The files are edited with the C API.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/TalCaptureSamples.h"
#include "support/TempDir.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {
namespace {

class TalCaptureForeignFileTest : public tofsim::test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    path_ = dir_ / "c.hdf5";
    writeTalCapture(path_, test::confocalSample());
    file_ = H5Fopen(path_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file_, 0);
  }
  void TearDown() override {
    closeFile();
    TempDirTest::TearDown();
  }
  void closeFile() {
    if (file_ >= 0) H5Fclose(file_);
    file_ = H5I_INVALID_HID;
  }

  /// Replaces `name` by a dataset of `type` and `dims` ({} = scalar) holding `data`.
  void replace(const char* name, hid_t type, const std::vector<hsize_t>& dims, const void* data) {
    if (H5Lexists(file_, name, H5P_DEFAULT) > 0) {
      ASSERT_GE(H5Ldelete(file_, name, H5P_DEFAULT), 0);
    }
    const hid_t space = dims.empty()
                            ? H5Screate(H5S_SCALAR)
                            : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t ds = H5Dcreate2(file_, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(ds, 0) << name;
    ASSERT_GE(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), 0) << name;
    H5Dclose(ds);
    H5Sclose(space);
  }

  std::string readError() {
    closeFile();
    try {
      readTalCapture(path_);
    } catch (const InputError& e) {
      return e.key();
    }
    return "no error";
  }

  std::filesystem::path path_;
  hid_t file_ = H5I_INVALID_HID;
};

TEST_F(TalCaptureForeignFileTest, ReadsTalRendersDtypes) {
  const TalCapture want = test::confocalSample();
  // tal render: int64 normals (here the sample's rounded: 0 or 1).
  std::vector<int64_t> normals(want.sensor_grid.normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) normals[i] = (i % 3 == 2) ? 1 : 0;
  replace("sensor_grid_normals", H5T_NATIVE_INT64, {5, 4, 3}, normals.data());
  // An enum stored as a plain int (older files), and tal's empty volume_format.
  const int32_t tSxSy = 1;
  replace("H_format", H5T_NATIVE_INT32, {1}, &tSxSy);
  const hid_t empty = H5Screate(H5S_NULL);
  const hid_t ds = H5Dcreate2(file_, "volume_format", H5T_IEEE_F64LE, empty, H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  H5Dclose(ds);
  H5Sclose(empty);
  closeFile();

  const TalCapture got = readTalCapture(path_);
  EXPECT_EQ(got.H_format, TalHFormat::T_Sx_Sy);
  EXPECT_EQ(got.H, want.H);
  ASSERT_EQ(got.sensor_grid.normals.size(), normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) {
    EXPECT_EQ(got.sensor_grid.normals[i], static_cast<float>(normals[i]));
  }
}

TEST_F(TalCaptureForeignFileTest, FlagStoredAsStringIsRefused) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, 5);
  replace("t_accounts_first_and_last_bounces", type, {}, "False");
  H5Tclose(type);
  EXPECT_EQ(readError(), "t_accounts_first_and_last_bounces");
}

TEST_F(TalCaptureForeignFileTest, SceneInfoAsGroupIsRefused) {
  ASSERT_GE(H5Ldelete(file_, "scene_info", H5P_DEFAULT), 0);
  const hid_t group = H5Gcreate2(file_, "scene_info", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(group, 0);
  H5Gclose(group);
  EXPECT_EQ(readError(), "scene_info");
}

TEST_F(TalCaptureForeignFileTest, OutOfRangeEnumIsRefused) {
  const int32_t seven = 7;
  replace("sensor_grid_format", H5T_NATIVE_INT32, {1}, &seven);
  EXPECT_EQ(readError(), "sensor_grid_format");
}

TEST_F(TalCaptureForeignFileTest, DisagreeingShapesAreRefused) {
  const std::vector<float> xyz(4 * 5 * 3, 0.5f);
  replace("sensor_grid_xyz", H5T_NATIVE_FLOAT, {4, 5, 3}, xyz.data());
  EXPECT_EQ(readError(), "sensor_grid_normals");  // (4, 5, 3) vs the normals' (5, 4, 3)
}

}  // namespace
}  // namespace tofsim::io
