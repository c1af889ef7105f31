// The file writeTalCapture makes, inspected through HDF5's C API against what
// tal.io.read_capture (y-tal 0.20.0) needs: exactly its 14 keys and the
// dtypes h5py gives tal render's values (shared/research/
// nlos-capture-format.md, section 1). The list here is written out on
// purpose, independent of the writer's own.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "io/TalCaptureSamples.h"
#include "support/TempDir.h"
#include "tofsim/io/TalCapture.h"

namespace tofsim::io {
namespace {

class TalCaptureLayoutTest : public tofsim::test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    writeTalCapture(dir_ / "c.hdf5", test::confocalSample());
    file_ = H5Fopen((dir_ / "c.hdf5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file_, 0);
  }
  void TearDown() override {
    if (file_ >= 0) H5Fclose(file_);
    TempDirTest::TearDown();
  }

  /// The dataset's type (class, size, ...) and shape; closes what it opens.
  struct Info {
    H5T_class_t cls = H5T_NO_CLASS;
    std::size_t size = 0;
    H5T_sign_t sign = H5T_SGN_ERROR;
    H5S_class_t space = H5S_NO_CLASS;
    std::vector<hsize_t> dims;
    std::map<std::string, long long> members;  // enum name -> value
    H5T_class_t baseClass = H5T_NO_CLASS;      // enum base type
    std::size_t baseSize = 0;
    H5T_sign_t baseSign = H5T_SGN_ERROR;
    bool variableString = false;
    H5T_cset_t cset = H5T_CSET_ERROR;
    H5D_layout_t layout = H5D_LAYOUT_ERROR;
  };
  Info info(const char* name) const {
    Info r;
    const hid_t ds = H5Dopen2(file_, name, H5P_DEFAULT);
    EXPECT_GE(ds, 0) << name;
    const hid_t type = H5Dget_type(ds);
    r.cls = H5Tget_class(type);
    r.size = H5Tget_size(type);
    if (r.cls == H5T_INTEGER) r.sign = H5Tget_sign(type);
    if (r.cls == H5T_ENUM) {
      const hid_t base = H5Tget_super(type);
      r.baseClass = H5Tget_class(base);
      r.baseSize = H5Tget_size(base);
      r.baseSign = H5Tget_sign(base);
      for (int i = 0; i < H5Tget_nmembers(type); ++i) {
        char* memberName = H5Tget_member_name(type, static_cast<unsigned>(i));
        long long value = 0;
        H5Tget_member_value(type, static_cast<unsigned>(i), &value);  // base size <= 8
        if (r.baseSize == 1) value = static_cast<signed char>(value & 0xFF);
        if (r.baseSize == 4) value = static_cast<int32_t>(value & 0xFFFFFFFF);
        r.members[memberName] = value;
        H5free_memory(memberName);
      }
      H5Tclose(base);
    }
    if (r.cls == H5T_STRING) {
      r.variableString = H5Tis_variable_str(type) > 0;
      r.cset = H5Tget_cset(type);
    }
    const hid_t space = H5Dget_space(ds);
    r.space = H5Sget_simple_extent_type(space);
    r.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, r.dims.data(), nullptr);
    const hid_t dcpl = H5Dget_create_plist(ds);
    r.layout = H5Pget_layout(dcpl);
    H5Pclose(dcpl);
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(ds);
    return r;
  }

  hid_t file_ = H5I_INVALID_HID;
};

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

TEST_F(TalCaptureLayoutTest, TopLevelKeysAreExactlyTals14) {
  std::vector<std::string> keys;
  ASSERT_GE(H5Literate(file_, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &keys), 0);
  std::vector<std::string> expected{"H",
                                    "H_format",
                                    "delta_t",
                                    "laser_grid_format",
                                    "laser_grid_normals",
                                    "laser_grid_xyz",
                                    "laser_xyz",
                                    "scene_info",
                                    "sensor_grid_format",
                                    "sensor_grid_normals",
                                    "sensor_grid_xyz",
                                    "sensor_xyz",
                                    "t_accounts_first_and_last_bounces",
                                    "t_start"};
  std::sort(keys.begin(), keys.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(keys, expected);
  for (const std::string& key : keys) {
    H5O_info_t object{};
    ASSERT_GE(H5Oget_info_by_name(file_, key.c_str(), &object, H5P_DEFAULT), 0);
    EXPECT_EQ(object.type, H5O_TYPE_DATASET) << key;  // scene_info a group would fail tal
  }
}

TEST_F(TalCaptureLayoutTest, HIsChunkedCompressedFloat32) {
  const Info h = info("H");
  EXPECT_EQ(h.cls, H5T_FLOAT);
  EXPECT_EQ(h.size, 4u);
  EXPECT_EQ(h.dims, (std::vector<hsize_t>{40, 5, 4}));
  EXPECT_EQ(h.layout, H5D_CHUNKED);
  const hid_t ds = H5Dopen2(file_, "H", H5P_DEFAULT);
  const hid_t dcpl = H5Dget_create_plist(ds);
  hsize_t chunk[3] = {};
  ASSERT_EQ(H5Pget_chunk(dcpl, 3, chunk), 3);
  EXPECT_EQ(std::vector<hsize_t>(chunk, chunk + 3), (std::vector<hsize_t>{40, 1, 4}));
  ASSERT_EQ(H5Pget_nfilters(dcpl), 2);
  unsigned flags = 0, level = 0;
  std::size_t n = 1;
  EXPECT_EQ(H5Pget_filter2(dcpl, 0, &flags, &n, &level, 0, nullptr, nullptr), H5Z_FILTER_SHUFFLE);
  n = 1;
  EXPECT_EQ(H5Pget_filter2(dcpl, 1, &flags, &n, &level, 0, nullptr, nullptr), H5Z_FILTER_DEFLATE);
  EXPECT_EQ(level, 4u);
  H5Pclose(dcpl);
  H5Dclose(ds);
}

TEST_F(TalCaptureLayoutTest, FormatsAreInt32EnumsOfShapeOne) {
  const std::map<std::string, long long> hFormat{
      {"UNKNOWN", 0}, {"T_Sx_Sy", 1}, {"T_Lx_Ly_Sx_Sy", 2}, {"T_Si", 3}, {"T_Li_Si", 4}};
  const std::map<std::string, long long> gridFormat{{"UNKNOWN", 0}, {"N_3", 1}, {"X_Y_3", 2}};
  for (const auto& [name, members] :
       {std::pair{"H_format", hFormat}, std::pair{"sensor_grid_format", gridFormat},
        std::pair{"laser_grid_format", gridFormat}}) {
    const Info e = info(name);
    EXPECT_EQ(e.cls, H5T_ENUM) << name;
    EXPECT_EQ(e.baseClass, H5T_INTEGER) << name;
    EXPECT_EQ(e.baseSize, 4u) << name;
    EXPECT_EQ(e.baseSign, H5T_SGN_2) << name;
    EXPECT_EQ(e.members, members) << name;
    EXPECT_EQ(e.space, H5S_SIMPLE) << name;
    EXPECT_EQ(e.dims, std::vector<hsize_t>{1}) << name;
  }
  // The stored values: T_Sx_Sy (1) and X_Y_3 (2), read as the enum's int32.
  int32_t value = 0;
  const hid_t ds = H5Dopen2(file_, "H_format", H5P_DEFAULT);
  const hid_t type = H5Dget_type(ds);
  ASSERT_GE(H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value), 0);
  EXPECT_EQ(value, 1);
  H5Tclose(type);
  H5Dclose(ds);
}

TEST_F(TalCaptureLayoutTest, TAccountsIsH5pysBool) {
  const Info b = info("t_accounts_first_and_last_bounces");
  EXPECT_EQ(b.cls, H5T_ENUM);
  EXPECT_EQ(b.baseClass, H5T_INTEGER);
  EXPECT_EQ(b.baseSize, 1u);
  EXPECT_EQ(b.baseSign, H5T_SGN_2);
  EXPECT_EQ(b.members, (std::map<std::string, long long>{{"FALSE", 0}, {"TRUE", 1}}));
  EXPECT_EQ(b.space, H5S_SCALAR);
}

TEST_F(TalCaptureLayoutTest, ScalarsPointsAndGrids) {
  for (const char* name : {"delta_t", "t_start"}) {
    const Info s = info(name);
    EXPECT_EQ(s.cls, H5T_FLOAT) << name;
    EXPECT_EQ(s.size, 8u) << name;
    EXPECT_EQ(s.space, H5S_SCALAR) << name;
  }
  for (const char* name : {"sensor_xyz", "laser_xyz"}) {
    const Info s = info(name);
    EXPECT_EQ(s.cls, H5T_FLOAT) << name;
    EXPECT_EQ(s.size, 4u) << name;
    EXPECT_EQ(s.dims, std::vector<hsize_t>{3}) << name;
    EXPECT_EQ(s.layout, H5D_CONTIGUOUS) << name;
  }
  for (const char* name :
       {"sensor_grid_xyz", "laser_grid_xyz", "sensor_grid_normals", "laser_grid_normals"}) {
    const Info g = info(name);
    EXPECT_EQ(g.cls, H5T_FLOAT) << name;
    EXPECT_EQ(g.size, 4u) << name;
    EXPECT_EQ(g.dims, (std::vector<hsize_t>{5, 4, 3})) << name;
    EXPECT_EQ(g.layout, H5D_CONTIGUOUS) << name;
  }
}

TEST_F(TalCaptureLayoutTest, SceneInfoIsOneVariableLengthUtf8String) {
  const Info s = info("scene_info");
  EXPECT_EQ(s.cls, H5T_STRING);
  EXPECT_TRUE(s.variableString);
  EXPECT_EQ(s.cset, H5T_CSET_UTF8);
  EXPECT_EQ(s.space, H5S_SCALAR);
}

}  // namespace
}  // namespace tofsim::io
