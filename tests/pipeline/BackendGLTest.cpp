// render.backend end to end: `cpu` renders with EGL made unavailable (it
// needs no EGL at all), `gl` still renders on llvmpipe, `auto` picks what the
// EGL device platform offers, and transient.json records the choice.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

using test::CommandResult;

// Tiny: the backends' agreement has its own tests (tests/cpu).
const std::string kSmall =
    " --set camera.resolution=[16,16] --set time.bins=100 --set render.shadow_map_resolution=128"
    " --set render.indirect.rsm_resolution=4 --set render.indirect.points_per_vpl=100"
    " --set sensors=[] --set output.video=false";

// No EGL: glvnd finds no vendor library, and the device platform (which has
// no hardware GPU here) is forced, so any context creation fails.
const std::string kNoEgl =
    "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent TOFSIM_EGL_PLATFORM=device ";

class BackendGLTest : public test::TempDirTest {
 protected:
  CommandResult render(const std::string& env, const std::string& backend) {
    return test::runCli("render " + test::kCornellConfig + " -o " + (dir_ / backend).string() +
                            kSmall + (backend.empty() ? "" : " --backend " + backend),
                        env);
  }
  // transient.json of the run into folder `backend`.
  std::string metadata(const std::string& backend) {
    return test::fileBytes((dir_ / backend / "transient.json").string());
  }
};

TEST_F(BackendGLTest, CpuNeedsNoEgl) {
  const CommandResult cpu = render(kNoEgl, "cpu");
  ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
  EXPECT_NE(cpu.output.find("device: CPU"), std::string::npos) << cpu.output;
  EXPECT_NE(metadata("cpu").find("\"backend\": \"cpu\""), std::string::npos) << metadata("cpu");
  EXPECT_NE(metadata("cpu").find("\"device\": \"CPU ("), std::string::npos) << metadata("cpu");
  // The same environment does take EGL away: gl cannot start in it.
  const CommandResult gl = render(kNoEgl, "gl");
  EXPECT_NE(gl.exitCode, 0) << gl.output;
  // And auto, finding no hardware GPU, falls back to the CPU.
  const CommandResult automatic = render(kNoEgl, "auto");
  ASSERT_EQ(automatic.exitCode, 0) << automatic.output;
  EXPECT_NE(metadata("auto").find("\"backend\": \"cpu\""), std::string::npos);
}

TEST_F(BackendGLTest, GlStillRendersWithoutAHardwareGpu) {
  const CommandResult gl = render("", "gl");
  ASSERT_EQ(gl.exitCode, 0) << gl.output;
  EXPECT_NE(metadata("gl").find("\"backend\": \"gl\""), std::string::npos) << metadata("gl");
  EXPECT_NE(gl.output.find("device: "), std::string::npos) << gl.output;
}

TEST_F(BackendGLTest, CpuThreadCountIsTakenAndLeavesTheBytes) {
  // render.threads: the CPU backend runs on that many threads (its device
  // line says so), and the volume is the same whatever the count.
  std::string bytes[2];
  const int counts[2] = {1, 3};
  for (int i = 0; i < 2; ++i) {
    const std::string out = (dir_ / ("threads" + std::to_string(counts[i]))).string();
    const CommandResult r =
        test::runCli("render " + test::kCornellConfig + " -o " + out + kSmall +
                     " --backend cpu --set render.threads=" + std::to_string(counts[i]));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string device = counts[i] == 1 ? "CPU (1 thread," : "CPU (3 threads,";
    EXPECT_NE(r.output.find(device), std::string::npos) << r.output;
    bytes[i] = test::fileBytes(out + "/transient.npy");
  }
  ASSERT_FALSE(bytes[0].empty());
  EXPECT_TRUE(bytes[0] == bytes[1]);
}

TEST_F(BackendGLTest, UnknownBackendIsALocatedError) {
  const CommandResult r = test::runCli("render " + test::kCornellConfig + " -o " +
                                       (dir_ / "x").string() + " --set render.backend=vulkan");
  EXPECT_EQ(r.exitCode, 1) << r.output;  // bad input
  EXPECT_NE(r.output.find("render.backend"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("auto, gl or cpu"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace tofsim
