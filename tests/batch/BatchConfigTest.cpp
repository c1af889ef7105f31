// Batch expansion (the config side, no rendering): product and zip counts,
// deterministic order and names, explicit runs, --set on every run, shards,
// and located errors for bad batch files.

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "support/TempDir.h"
#include "tofsim/config/BatchConfig.h"
#include "tofsim/pipeline/BatchRun.h"
#include "tofsim/util/Error.h"

namespace tofsim {
namespace {

using config::BatchConfig;
using config::loadBatchConfig;

const std::string kBase = std::string(TOFSIM_SOURCE_DIR) + "/configs/cornell_box.yaml";

class BatchConfigTest : public test::TempDirTest {
 protected:
  std::filesystem::path write(const std::string& body) {
    const auto path = dir_ / "batch.yaml";
    std::ofstream(path) << "base: " << kBase << "\n" << body;
    return path;
  }
  std::string errorOf(const std::string& body) {
    try {
      loadBatchConfig(write(body));
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(BatchConfigTest, ProductTimesZipInDocumentedOrder) {
  const BatchConfig b = loadBatchConfig(write(R"(
output: sweep
set: {time.bins: 50}
sweep:
  product:
    light.offset: [[0.05, 0, 0], [0.1, 0, 0]]
    sensors.0.jitter_fwhm: ["30 ps", "80 ps", "120 ps"]
  zip:
    camera.resolution: [[16, 16], [32, 32]]
    time.bin_width: ["10 ps", "20 ps"]
)"));
  ASSERT_EQ(b.runs.size(), 2u * 3u * 2u);
  EXPECT_EQ(b.output_root, dir_ / "sweep");
  // First product key slowest, the zip group fastest.
  EXPECT_EQ(b.runs[0].name,
            "run0000_offset-0.05,0,0_jitter_fwhm-30ps_resolution-16,16_bin_width-10ps");
  EXPECT_EQ(b.runs[1].name,
            "run0001_offset-0.05,0,0_jitter_fwhm-30ps_resolution-32,32_bin_width-20ps");
  EXPECT_EQ(b.runs[2].varied[1].value, "80 ps");
  EXPECT_EQ(b.runs[6].varied[0].value, "[0.1, 0, 0]");
  // `set` first, then the sweep values.
  ASSERT_EQ(b.runs[11].overrides.size(), 5u);
  EXPECT_EQ(b.runs[11].overrides[0].keyPath, "time.bins");
  EXPECT_EQ(b.runs[11].overrides[4].value, "20 ps");
  std::set<std::string> names;
  for (const auto& r : b.runs) names.insert(r.name);
  EXPECT_EQ(names.size(), b.runs.size());
}

TEST_F(BatchConfigTest, ZipAloneAndExplicitRunsAndCliOverrides) {
  const BatchConfig b = loadBatchConfig(write(R"(
sweep:
  zip:
    time.bins: [100, 200, 300]
    render.seed: [1, 2, 3]
runs:
  - name: baseline
    set: {render.seed: 7}
  - set: {sensors: [{type: spad, bins: 10}]}
)"),
                                        {config::Override{"camera.resolution", "[16,16]"}});
  ASSERT_EQ(b.runs.size(), 5u);
  EXPECT_EQ(b.runs[2].name, "run0002_bins-300_seed-3");
  EXPECT_EQ(b.runs[3].name, "baseline");
  EXPECT_EQ(b.runs[3].index, 3u);
  EXPECT_EQ(b.runs[4].name, "run0004");
  for (const auto& r : b.runs) EXPECT_EQ(r.overrides.back().keyPath, "camera.resolution");
  EXPECT_EQ(b.runs[3].overrides.front().value, "7");
  EXPECT_EQ(b.runs[4].overrides.front().value, "[{type: spad, bins: 10}]");
}

TEST_F(BatchConfigTest, NoSweepIsOneRun) {
  const BatchConfig b = loadBatchConfig(write("set: {time.bins: 20}\n"));
  ASSERT_EQ(b.runs.size(), 1u);
  EXPECT_EQ(b.runs[0].name, "run0000");
}

TEST_F(BatchConfigTest, LocatedErrors) {
  EXPECT_NE(errorOf("swep: {}\n").find("batch.yaml:2:1: swep: unknown key"), std::string::npos)
      << errorOf("swep: {}\n");
  EXPECT_NE(errorOf("sweep:\n  zip:\n    time.bins: [1, 2]\n    render.seed: [1]\n")
                .find("zip lists must have equal length"),
            std::string::npos);
  EXPECT_NE(errorOf("sweep:\n  product:\n    time.bins: []\n").find("must not be empty"),
            std::string::npos);
  EXPECT_NE(errorOf("runs:\n  - name: a\n  - name: a\n").find("used twice"), std::string::npos);
  EXPECT_NE(errorOf("runs:\n  - name: a/b\n").find("batch.yaml:3:11"), std::string::npos)
      << errorOf("runs:\n  - name: a/b\n");
  EXPECT_NE(errorOf("runs:\n  - nam: a\n").find("unknown key"), std::string::npos);
}

TEST_F(BatchConfigTest, ValidationNamesTheRun) {
  const BatchConfig b =
      loadBatchConfig(write("runs:\n  - name: ok\n  - name: bad\n"
                            "    set: {time.bins: -3}\n"));
  try {
    config::validateBatch(b);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("run bad:"), std::string::npos) << m;
    EXPECT_NE(m.find("time.bins"), std::string::npos) << m;
    EXPECT_EQ(m.find("run ok:"), std::string::npos) << m;
  }
}

TEST(BatchShardTest, ShardsPartitionTheRuns) {
  for (int n : {1, 2, 3, 5}) {
    for (std::size_t i = 0; i < 17; ++i) {
      int owners = 0;
      for (int k = 1; k <= n; ++k) owners += pipeline::inShard(i, k, n) ? 1 : 0;
      EXPECT_EQ(owners, 1) << i << " in shards of " << n;
    }
  }
  int k = 0, n = 0;
  pipeline::parseShard("2/3", k, n);
  EXPECT_EQ(k, 2);
  EXPECT_EQ(n, 3);
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "1/3x"}) {
    EXPECT_THROW(pipeline::parseShard(bad, k, n), InputError) << bad;
  }
}

}  // namespace
}  // namespace tofsim
