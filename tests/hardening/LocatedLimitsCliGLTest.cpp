// Issue 39: inputs that aborted tofsim (exit 134, a crash) mid-run and left a
// staging folder behind now end in a located error before anything renders:
// an IRF whose t0 lies far outside it (validate called it ok; render and
// sense hit CHECK(total > 0.0) in TimeKernel.cpp), and a glTF animation
// keyframe at 1e30 m (Embree's ray.valid() assertion, or a crash, at the
// first frame). Each runs the CLI; TOFSIM_TEST_CLI=<older tofsim> shows the
// old behaviour.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using test::runCli;

// What a failed run left in the output folder other than its lock: staging
// folders (".frame_00000.tofsim-staging-*", ".tofsim-staging-*") and results.
std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> names;
  if (!fs::exists(dir)) return names;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name != ".tofsim.lock") names.push_back(name);
  }
  return names;
}

class LocatedLimitsCliGLTest : public test::TempDirTest {
 protected:
  // A 4 x 4 pixel, 16 bin CPU render of the Cornell box with a SPAD that
  // reads the shipped measured IRF.
  fs::path writeSpadConfig() {
    const fs::path config = dir_ / "spad.yaml";
    std::ofstream(config) << "scene: " TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf\n"
                             "camera: {gltf_camera: cornell_camera, resolution: [4, 4]}\n"
                             "light: {type: point, position: [0.28, 0.5, 0.28]}\n"
                             "time: {start: 1.5 m, bin_width: 10 ps, bins: 16}\n"
                             "render: {backend: cpu, indirect: {enabled: false}}\n"
                             "output: {video: false}\n"
                             "sensors:\n"
                             "  - type: spad\n"
                             "    cycles: 10\n"
                             "    irf: {file: " TOFSIM_SOURCE_DIR
                             "/configs/irf/spad_exgauss_2ps.csv}\n";
    return config;
  }
};

TEST_F(LocatedLimitsCliGLTest, IrfTimeZeroFarOutsideItIsALocatedErrorEverywhere) {
  const fs::path config = writeSpadConfig();
  for (const std::string t0 : {"1 s", "-1 s"}) {
    SCOPED_TRACE(t0);
    const std::string set = " --set 'sensors.0.irf.t0=" + t0 + "'";
    const test::CommandResult validate = runCli("validate " + config.string() + set);
    EXPECT_EQ(validate.exitCode, 1) << validate.output;
    EXPECT_NE(validate.output.find("sensors[0].irf.t0"), std::string::npos) << validate.output;
    EXPECT_NE(validate.output.find("lies outside the response"), std::string::npos)
        << validate.output;
    const fs::path out = dir_ / "out";
    const test::CommandResult render = runCli("render " + config.string() + " -q -o " +
                                              out.string() + set);
    EXPECT_EQ(render.exitCode, 1) << render.output;
    EXPECT_NE(render.output.find("sensors[0].irf.t0"), std::string::npos) << render.output;
    EXPECT_TRUE(leftovers(out).empty()) << render.output;
  }
  // sense on a saved render: the same located error, the render's files kept.
  const fs::path saved = dir_ / "saved";
  const test::CommandResult ok = runCli("render " + config.string() + " -q -o " + saved.string());
  ASSERT_EQ(ok.exitCode, 0) << ok.output;
  const std::vector<std::string> before = leftovers(saved);
  const test::CommandResult sense = runCli("sense " + config.string() + " -q --volume " +
                                           saved.string() + " --set 'sensors.0.irf.t0=1 s'");
  EXPECT_EQ(sense.exitCode, 1) << sense.output;
  EXPECT_NE(sense.output.find("sensors[0].irf.t0"), std::string::npos) << sense.output;
  EXPECT_EQ(leftovers(saved), before);
}

TEST_F(LocatedLimitsCliGLTest, JitterOfSecondsIsALocatedErrorNotAnAbort) {
  const fs::path config = writeSpadConfig();
  const fs::path out = dir_ / "out";
  // The IRF replaced by a Gaussian jitter of 1 s on 10 ps bins.
  const test::CommandResult r =
      runCli("render " + config.string() + " -q -o " + out.string() +
             " --set 'sensors.0={type: spad, cycles: 10, jitter_fwhm: 1 s}'");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("sensors[0].jitter_fwhm"), std::string::npos) << r.output;
  EXPECT_TRUE(leftovers(out).empty()) << r.output;
}

// tests/regressions/sequence/translation_1e30: a config, NUL, a glTF whose
// plate a LINEAR translation carries to 1e30 m at its keyframe 1.
TEST_F(LocatedLimitsCliGLTest, KeyframeAt1e30FailsBeforeTheFirstFrame) {
  std::ifstream in(fs::path(TOFSIM_SOURCE_DIR) / "tests/regressions/sequence/translation_1e30",
                   std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  const std::size_t nul = bytes.find('\0');
  ASSERT_NE(nul, std::string::npos);
  std::ofstream(dir_ / "seq.yaml") << bytes.substr(0, nul);
  std::ofstream(dir_ / "input.gltf") << bytes.substr(nul + 1);
  const test::CommandResult validate = runCli("validate " + (dir_ / "seq.yaml").string());
  EXPECT_EQ(validate.exitCode, 1) << validate.output;
  EXPECT_NE(validate.output.find("keyframe 1"), std::string::npos) << validate.output;
  const fs::path out = dir_ / "out";
  const test::CommandResult r =
      runCli("render " + (dir_ / "seq.yaml").string() + " -q -o " + out.string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("input.gltf"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("animation[0].channels[0] 'move'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("keyframe 1 (translation at 1 s)"), std::string::npos) << r.output;
  EXPECT_TRUE(leftovers(out).empty()) << r.output;
}

}  // namespace
}  // namespace tofsim
