// The video and the frames come from a bin-major temporary file, fed segment
// by segment (BinMajorSpill): frame t of the EXRs is bin t of transient.npy,
// the pictures do not depend on how the render was cut into segments, and
// the temporary is gone after the run (after a failed or interrupted one it
// goes with the staging folder: FaultInjectionGLTest's interrupted renders
// have the video on).

#include <gtest/gtest.h>

#include <filesystem>

#include "pipeline/CliRun.h"
#include "pipeline/StatsJson.h"
#include "support/TempDir.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;
using test::runCli;

// 48x48 pixels, 60 bins (a 1.6 MiB segment of both components), frames,
// frame PNGs with a window of 3 bins over a stride of 2, and the video.
const std::string kFrames =
    " --backend cpu --set camera.resolution=[48,48] --set time.bins=60 --set sensors=[]"
    " --set render.shadow_map_resolution=256 --set render.indirect.rsm_resolution=4"
    " --set render.indirect.points_per_vpl=200 --set output.frames=true"
    " --set output.frame_pngs=true --set output.video=true --set output.video_stride=2"
    " --set output.video_window=3 -q";

bool anyTemporary(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  }
  return false;
}

class VideoFramesGLTest : public test::TempDirTest {};

TEST_F(VideoFramesGLTest, FramesAreTheVolumesBinsWhateverTheSegments) {
  const fs::path cut = dir_ / "cut", whole = dir_ / "whole";
  const test::CommandResult a = runCli("render " + test::kCornellConfig + " -o " + cut.string() +
                                       kFrames + " --set render.memory_budget=1MiB");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  EXPECT_GE(test::jsonNumber(cut / "transient.json", "segments"), 3.0);
  const test::CommandResult b =
      runCli("render " + test::kCornellConfig + " -o " + whole.string() + kFrames);
  ASSERT_EQ(b.exitCode, 0) << b.output;
  EXPECT_EQ(test::jsonNumber(whole / "transient.json", "segments"), 1.0);
  EXPECT_FALSE(anyTemporary(cut));
  EXPECT_FALSE(anyTemporary(whole));

  const io::NpyArray volume = io::readNpy(cut / "transient.npy");
  const std::size_t H = volume.shape[0], W = volume.shape[1], T = volume.shape[2], C = 3;
  for (const std::size_t t : {std::size_t{0}, std::size_t{17}, T - 1}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.exr", t);
    const Image frame = io::readExr(cut / "frames" / name);
    ASSERT_EQ(frame.data.size(), H * W * C);
    for (std::size_t p = 0; p < H * W; ++p) {
      for (std::size_t c = 0; c < C; ++c) {
        ASSERT_EQ(frame.data[p * C + c], volume.data[(p * T + t) * C + c]) << name << " " << p;
      }
    }
  }
  int pngs = 0;
  for (const auto& e : fs::directory_iterator(cut / "frames")) {
    const fs::path other = whole / "frames" / e.path().filename();
    EXPECT_TRUE(test::fileBytes(e.path().string()) == test::fileBytes(other.string()))
        << e.path().filename();
    pngs += e.path().extension() == ".png";
  }
  EXPECT_EQ(pngs, 30);
  EXPECT_GT(fs::file_size(cut / "transient.mp4"), 0u);
}

}  // namespace
}  // namespace tofsim
