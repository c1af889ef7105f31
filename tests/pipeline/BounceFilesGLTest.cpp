// Bounce-resolved output end to end: `output.components: [bounce1, bounce2]`
// with render.indirect.bounces: 2 writes bounce1.npy and bounce2.npy next to
// direct.npy and indirect.npy on both backends, with transient = direct +
// indirect and indirect = bounce1 + bounce2 exactly, in float; a bounce above
// the render's is a located error before anything renders.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

using test::CommandResult;

// The Cornell config's whole axis (640 bins, 1.5 .. 3.42 m): room for the second bounce.
const std::string kSmall =
    " --set camera.resolution=[16,16] --set time.bins=640 --set render.shadow_map_resolution=128"
    " --set render.indirect.rsm_resolution=4 --set render.indirect.points_per_vpl=100"
    " --set sensors=[] --set output.video=false --set render.indirect.bounces=2";

class BounceFilesGLTest : public test::TempDirTest,
                          public ::testing::WithParamInterface<std::string> {
 protected:
  std::vector<float> volume(const std::string& name) {
    return io::readNpy(dir_ / "out" / (name + ".npy")).data;
  }
};

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST_P(BounceFilesGLTest, BounceFilesAddUpToIndirectAndTransient) {
  const CommandResult r = test::runCli(
      "render " + test::kCornellConfig + " -o " + (dir_ / "out").string() + kSmall + " --backend " +
      GetParam() + " --set output.components=[direct,indirect,bounce1,bounce2]");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::vector<float> transient = volume("transient"), direct = volume("direct"),
                           indirect = volume("indirect"), b1 = volume("bounce1"),
                           b2 = volume("bounce2");
  ASSERT_EQ(b2.size(), transient.size());
  std::vector<float> sum(b1.size()), total(direct.size());
  double e1 = 0.0, e2 = 0.0;
  for (std::size_t i = 0; i < sum.size(); ++i) {
    sum[i] = b1[i] + b2[i];
    total[i] = direct[i] + indirect[i];
    e1 += b1[i];
    e2 += b2[i];
  }
  EXPECT_TRUE(sameBytes(sum, indirect));
  EXPECT_TRUE(sameBytes(total, transient));
  EXPECT_GT(e2, 0.0);  // the Cornell box's second bounce carries light
  EXPECT_LT(e2, e1);
}

INSTANTIATE_TEST_SUITE_P(Backends, BounceFilesGLTest, ::testing::Values("cpu", "gl"));

class BounceFilesCliTest : public test::TempDirTest {};

TEST_F(BounceFilesCliTest, BounceAboveTheRendersIsALocatedError) {
  const CommandResult r =
      test::runCli("render " + test::kCornellConfig + " -o " + (dir_ / "x").string() + kSmall +
                   " --set output.components=[bounce1,bounce3]");
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("output.components[1]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bounce3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("render.indirect.bounces: 2"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x" / "transient.npy"));
}

}  // namespace
}  // namespace tofsim
