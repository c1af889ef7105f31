#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "support/TempDir.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {
namespace {

class ExrTest : public test::TempDirTest {};

Image patterned(int w, int h, int c) {
  Image image(w, h, c);
  for (std::size_t i = 0; i < image.data.size(); ++i) {
    // Values that would not survive a half-float or lossy path.
    image.data[i] = std::ldexp(1.0f + float(i) * 1e-6f, int(i % 40) - 20) * ((i % 3) ? 1.f : -1.f);
  }
  image.data[0] = std::numeric_limits<float>::denorm_min();
  return image;
}

void expectRoundTrip(const std::filesystem::path& path, const std::vector<std::string>& names) {
  const Image image = patterned(7, 5, static_cast<int>(names.size()));
  writeExr(path, image, names);
  std::vector<std::string> readNames;
  const Image back = readExr(path, &readNames);
  EXPECT_EQ(readNames, names);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  ASSERT_EQ(back.channels, image.channels);
  ASSERT_EQ(back.data.size(), image.data.size());
  EXPECT_EQ(std::memcmp(back.data.data(), image.data.data(), image.data.size() * sizeof(float)), 0);
}

TEST_F(ExrTest, RoundTripOneChannel) { expectRoundTrip(dir_ / "z.exr", {"Z"}); }
TEST_F(ExrTest, RoundTripThreeChannels) { expectRoundTrip(dir_ / "rgb.exr", {"R", "G", "B"}); }
TEST_F(ExrTest, RoundTripFourChannels) { expectRoundTrip(dir_ / "rgba.exr", {"R", "G", "B", "A"}); }
TEST_F(ExrTest, RoundTripKeepsArbitraryOrder) {
  expectRoundTrip(dir_ / "any.exr", {"depth_m", "amplitude", "phase_rad"});
}

TEST_F(ExrTest, DepthIsWrittenAsYAndZAndReadBackFromEitherForm) {
  const Image depth = patterned(6, 4, 1);
  writeDepthExr(dir_ / "depth.exr", depth);
  std::vector<std::string> names;
  const Image both = readExr(dir_ / "depth.exr", &names);
  EXPECT_EQ(names, (std::vector<std::string>{"Y", "Z"}));
  for (std::size_t i = 0; i < depth.data.size(); ++i) {
    ASSERT_EQ(both.data[2 * i], depth.data[i]);
    ASSERT_EQ(both.data[2 * i + 1], depth.data[i]);
  }
  EXPECT_EQ(readDepthExr(dir_ / "depth.exr").data, depth.data);
  // Folders written by older versions hold Z alone; a grey image Y alone.
  for (const char* name : {"Z", "Y"}) {
    writeExr(dir_ / "one.exr", depth, {name});
    const Image back = readDepthExr(dir_ / "one.exr");
    EXPECT_EQ(back.channels, 1);
    EXPECT_EQ(back.data, depth.data) << name;
  }
  writeExr(dir_ / "rgb.exr", patterned(2, 2, 3), {"R", "G", "B"});
  EXPECT_THROW(readDepthExr(dir_ / "rgb.exr"), InputError);
}

TEST_F(ExrTest, LeavesOnlyTheFinalFile) {
  writeExr(dir_ / "only.exr", patterned(3, 2, 1), {"Y"});
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir_)) {
    EXPECT_EQ(e.path().filename(), "only.exr");
    ++n;
  }
  EXPECT_EQ(n, 1u);
}

// The temporary's name is guessable: a link planted there (at this or the
// earlier "<name>.tmp-<pid>.exr") is neither written through nor kept.
TEST_F(ExrTest, ALinkAtTheTemporaryNameIsNotFollowed) {
  const std::filesystem::path file = dir_ / "z.exr", victim = dir_ / "victim.txt";
  std::ofstream(victim) << "precious";
  const std::string temp = file.string() + ".tmp-" + std::to_string(::getpid());
  std::filesystem::create_symlink(victim, temp);
  std::filesystem::create_symlink(victim, temp + ".exr");
  expectRoundTrip(file, {"Z"});
  EXPECT_FALSE(std::filesystem::is_symlink(file));
  std::ifstream in(victim);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "precious");
}

TEST_F(ExrTest, ErrorsNameTheFile) {
  EXPECT_THROW(writeExr(dir_ / "bad.exr", patterned(2, 2, 2), {"R"}), InputError);
  EXPECT_THROW(writeExr(dir_ / "no_such_dir" / "x.exr", patterned(2, 2, 1), {"Y"}), InputError);
  try {
    readExr(dir_ / "absent.exr");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.exr"), std::string::npos);
  }
  std::ofstream(dir_ / "garbage.exr") << "not an exr";
  try {
    readExr(dir_ / "garbage.exr");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("garbage.exr"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tofsim::io
