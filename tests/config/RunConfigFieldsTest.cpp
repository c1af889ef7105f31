// The run config's parameter tables (apps/config/src/RunFields.h) against the
// structs: the documented default of every table key, written into a config,
// must give the same effective config as leaving the key out.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

class RunConfigFieldsTest : public test::TempDirTest {
 protected:
  std::string effective(const std::string& extra) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml") << "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n"
                                   << extra;
    return effectiveConfigYaml(loadRunConfig(dir_ / "c.yaml"));
  }
  /// The InputError `extra` gives, "" when it loads.
  std::string errorOf(const std::string& extra) {
    try {
      effective(extra);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(RunConfigFieldsTest, TableDocumentedDefaultsReadBackAsTheStructDefaults) {
  const std::string defaults = effective("");
  int checked = 0;
  for (const std::string section : {"indirect", "reference"}) {
    const std::string prefix = "render." + section + ".";
    for (const ConfigKey& key : runConfigKeys()) {
      const std::string path = key.path;
      if (path.rfind(prefix, 0) != 0) continue;
      const std::string name = path.substr(prefix.size());
      SCOPED_TRACE(path + ": " + key.defaultValue);
      EXPECT_EQ(
          effective("render:\n  " + section + ":\n    " + name + ": " + key.defaultValue + "\n"),
          defaults)
          << "the documented default of `" << path << "` is not the struct's";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 16 + 6);
}

TEST_F(RunConfigFieldsTest, OutputFormatIsNpyOrHdf5WithALocatedError) {
  EXPECT_EQ(effective("output:\n  format: npy\n"), effective(""));
  EXPECT_NE(effective("output:\n  format: hdf5\n").find("format: hdf5"), std::string::npos);
  const std::string what = errorOf("output:\n  format: zarr\n");
  ASSERT_FALSE(what.empty()) << "format: zarr was accepted";
  EXPECT_NE(what.find("c.yaml:6:"), std::string::npos) << what;
  EXPECT_NE(what.find("output.format"), std::string::npos) << what;
  EXPECT_NE(what.find("zarr"), std::string::npos) << what;
}

// render.indirect.merge_pixel_samples is the CPU backend's: with the gl
// backend a located error; auto and cpu take it, and without pixel samples
// it has nothing to merge.
TEST_F(RunConfigFieldsTest, MergedPixelSamplesOnTheGlBackendAreALocatedError) {
  const std::string merged = "    merge_pixel_samples: true\n";
  EXPECT_NE(effective("render:\n  backend: cpu\n  pixel_samples: 2\n  indirect:\n" + merged)
                .find("merge_pixel_samples: true"),
            std::string::npos);
  EXPECT_NO_THROW(effective("render:\n  pixel_samples: 2\n  indirect:\n" + merged));
  EXPECT_NO_THROW(effective("render:\n  backend: gl\n  indirect:\n" + merged));
  const std::string what =
      errorOf("render:\n  backend: gl\n  pixel_samples: 2\n  indirect:\n" + merged);
  ASSERT_FALSE(what.empty()) << "merge_pixel_samples on the gl backend was accepted";
  EXPECT_NE(what.find("c.yaml:9:"), std::string::npos) << what;
  EXPECT_NE(what.find("render.indirect.merge_pixel_samples"), std::string::npos) << what;
  EXPECT_NE(what.find("backend: cpu"), std::string::npos) << what;
}

// render.indirect.gather_pairs is the CPU backend's too: with the gl backend
// a located error; auto and cpu take it, and 0 (every pair) runs anywhere.
TEST_F(RunConfigFieldsTest, SampledGatherOnTheGlBackendIsALocatedError) {
  const std::string sampled = "  indirect:\n    gather_pairs: 512\n";
  EXPECT_NE(effective("render:\n  backend: cpu\n" + sampled).find("gather_pairs: 512"),
            std::string::npos);
  EXPECT_NO_THROW(effective("render:\n" + sampled));
  EXPECT_NO_THROW(effective("render:\n  backend: gl\n  indirect:\n    gather_pairs: 0\n"));
  const std::string what = errorOf("render:\n  backend: gl\n" + sampled);
  ASSERT_FALSE(what.empty()) << "gather_pairs on the gl backend was accepted";
  EXPECT_NE(what.find("c.yaml:8:"), std::string::npos) << what;
  EXPECT_NE(what.find("render.indirect.gather_pairs"), std::string::npos) << what;
  EXPECT_NE(what.find("backend: cpu"), std::string::npos) << what;
}

}  // namespace
}  // namespace tofsim::config
