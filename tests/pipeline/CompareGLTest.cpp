// `tofsim render --renderer reference` and `tofsim compare` end to end: the
// reference writes the same kind of output directory, and compare measures
// the IR render against it.

#include <gtest/gtest.h>

#include <sstream>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

using test::runCli;

const std::string kTiny =
    " --set camera.resolution=[16,16] --set time.bins=120 --set time.bin_width=30ps"
    " --set sensors=[] --set render.shadow_map_resolution=256 -q";

class CompareGLTest : public test::TempDirTest {};

TEST_F(CompareGLTest, ReferenceRendersAndCompareMeasuresTheIrRenderAgainstIt) {
  const std::string ir = (dir_ / "ir").string(), ref = (dir_ / "ref").string();
  const auto a =
      runCli("render " + test::kCornellConfig + " -o " + ir + kTiny +
             " --set render.indirect.visibility=exact --set render.indirect.geometry_clamp=0");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  const auto b = runCli("render " + test::kCornellConfig + " -o " + ref + kTiny +
                        " --renderer reference --set render.reference.samples_per_pixel=64");
  ASSERT_EQ(b.exitCode, 0) << b.output;
  EXPECT_NE(test::fileBytes(ref + "/transient.json").find("\"renderer\": \"reference\""),
            std::string::npos);

  const auto c = runCli("compare " + ir + " " + ref + " -o " + (dir_ / "cmp").string());
  ASSERT_EQ(c.exitCode, 0) << c.output;
  EXPECT_NE(c.output.find("steady relative L1"), std::string::npos) << c.output;
  for (const char* f :
       {"compare_energy.csv", "compare_energy.png", "compare_arrival.exr", "compare_arrival.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir_ / "cmp" / f)) << f;
  }
  // The CSV has a header and one line per bin.
  const std::string csv = test::fileBytes((dir_ / "cmp" / "compare_energy.csv").string());
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 121);
}

TEST_F(CompareGLTest, CompareMeasuresEveryComponentBothRendersWrote) {
  // Two IR renders with three bounces: one on the CPU backend with every
  // component, one on GL with direct and bounce2 only. The components in both
  // are compared; a render with itself gives zero error.
  const std::string cpu = (dir_ / "cpu").string(), gl = (dir_ / "gl").string();
  const std::string bounces =
      " --set render.indirect.bounces=3 --set render.indirect.rsm_resolution=8";
  ASSERT_EQ(
      runCli("render " + test::kCornellConfig + " -o " + cpu + kTiny + bounces +
             " --backend cpu --set output.components=[direct,indirect,bounce1,bounce2,bounce3]")
          .exitCode,
      0);
  ASSERT_EQ(runCli("render " + test::kCornellConfig + " -o " + gl + kTiny + bounces +
                   " --backend gl --set output.components=[direct,bounce2]")
                .exitCode,
            0);
  const auto c = runCli("compare " + gl + " " + cpu + " -o " + (dir_ / "cmp").string());
  ASSERT_EQ(c.exitCode, 0) << c.output;
  EXPECT_NE(c.output.find("components (in both A and B)"), std::string::npos) << c.output;
  const std::string csv = test::fileBytes((dir_ / "cmp" / "compare_components.csv").string());
  // Header, direct, bounce2: what both wrote, in that order.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3) << csv;
  EXPECT_EQ(csv.find("direct,"), csv.find('\n') + 1) << csv;
  EXPECT_NE(csv.find("\nbounce2,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("indirect,"), std::string::npos) << csv;
  // The two backends agree closely on every shared component.
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    const double transientL1 = std::stod(line.substr(line.rfind(',') + 1));
    EXPECT_LT(transientL1, 0.05) << line;
  }
  const auto self = runCli("compare " + cpu + " " + cpu + " -o " + (dir_ / "self").string());
  ASSERT_EQ(self.exitCode, 0) << self.output;
  const std::string selfCsv = test::fileBytes((dir_ / "self" / "compare_components.csv").string());
  EXPECT_EQ(std::count(selfCsv.begin(), selfCsv.end(), '\n'), 6) << selfCsv;
  EXPECT_NE(selfCsv.find("bounce3,0,0,0"), std::string::npos) << selfCsv;
}

TEST_F(CompareGLTest, CompareRejectsMismatchedVolumesAndMissingDirectories) {
  const std::string a = (dir_ / "a").string(), b = (dir_ / "b").string();
  ASSERT_EQ(runCli("render " + test::kCornellConfig + " -o " + a + kTiny).exitCode, 0);
  ASSERT_EQ(runCli("render " + test::kCornellConfig + " -o " + b + kTiny + " --set time.bins=60")
                .exitCode,
            0);
  const auto mismatch = runCli("compare " + a + " " + b);
  EXPECT_EQ(mismatch.exitCode, 1);
  EXPECT_NE(mismatch.output.find("error"), std::string::npos) << mismatch.output;
  const auto missing = runCli("compare " + a + " " + (dir_ / "nowhere").string());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("nowhere"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace tofsim
