// `tofsim info` on a generated animated glTF: each animation's name, span and
// channels (node, path, interpolation, keyframes) and what it ignores.
#include <gtest/gtest.h>

#include <string>

#include "scene/AnimatedGltfFiles.h"
#include "support/TempDir.h"
#include "tofsim/pipeline/SceneInfo.h"

namespace tofsim::pipeline {
namespace {

class SceneInfoAnimationTest : public test::TempDirTest {};

TEST_F(SceneInfoAnimationTest, ListsChannelsAndWhatIsIgnored) {
  test::AnimatedGltf f;
  f.addChannel(1, "translation", {0.5, 1.5, 2.5}, {0, 0, 5, 1, 0, 5, 2, 0, 5}, "LINEAR");
  f.addChannel(0, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, 0, 1}, "STEP");
  f.addChannel(0, "weights", {0, 1}, {0, 1}, "LINEAR");
  const auto path =
      test::writeText(dir_ / "anim.gltf",
                      f.json(R"([{"mesh": 0, "skin": 0}, {"camera": 0, "name": "cam"}])", "[0, 1]",
                             R"(, "skins": [{"joints": [0]}],
               "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}])"));
  const std::string text = describeScene(path);
  const auto has = [&](const std::string& s) {
    EXPECT_NE(text.find(s), std::string::npos) << "missing '" << s << "' in\n" << text;
  };
  has("animations: 1 (played together, 0 .. 2.5 s; moving: 1 mesh(es), 1 camera(s))");
  has("[0] anim");
  has("0 .. 2.5 s (duration 2.5 s), 2 channel(s)");
  has("node[1] 'cam'");
  has("translation LINEAR      3 keyframes");
  has("node[0]              rotation    STEP        2 keyframes");
  has("ignored: 1 morph-target weights channel(s)");
  has("1 skin(s) ignored");
}

TEST_F(SceneInfoAnimationTest, StaticSceneSaysNoAnimations) {
  const auto path =
      test::writeText(dir_ / "static.gltf", test::AnimatedGltf().json(R"([{"mesh": 0}])", "[0]"));
  EXPECT_NE(describeScene(path).find("animations: 0\n"), std::string::npos);
}

}  // namespace
}  // namespace tofsim::pipeline
