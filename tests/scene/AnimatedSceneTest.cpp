// glTF animations: each sampler mode against values worked out by hand from
// the glTF 2.0 rules, clamping, cameras, parent-child composition, the static
// path's bytes and the located errors of bad animation data.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "AnimatedGltfFiles.h"
#include "support/TempDir.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene {
namespace {

using test::AnimatedGltf;
using test::writeText;

constexpr double kTol = 1e-6;                           // float keyframes, double arithmetic
const float kS45 = static_cast<float>(std::sqrt(0.5));  // sin 45 deg = cos 45 deg

class AnimatedSceneTest : public test::TempDirTest {
 protected:
  AnimatedScene load(const AnimatedGltf& file, const std::string& nodes = R"([{"mesh": 0}])",
                     const std::string& roots = "[0]", const std::string& extra = "") {
    path_ = writeText(dir_ / "anim.gltf", file.json(nodes, roots, extra));
    return AnimatedScene::load(path_);
  }
  std::string errorOf(const AnimatedGltf& file, const std::string& nodes = R"([{"mesh": 0}])") {
    try {
      load(file, nodes);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  std::filesystem::path path_;
};

// Where the triangle's vertex v (0: (0,0,0), 1: (1,0,0), 2: (0,1,0)) of mesh m is at t.
glm::dvec3 vertexAt(const AnimatedScene& s, double t, int v = 0, std::size_t m = 0) {
  return glm::dvec3(s.sceneAt(t).meshes.at(m).positions_world.at(v));
}

void expectNear(const glm::dvec3& got, const glm::dvec3& want, double tol = kTol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

TEST_F(AnimatedSceneTest, StepHoldsEachKeyframeUntilTheNext) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1, 2}, {0, 0, 0, 1, 0, 0, 3, 0, 0}, "STEP");
  const AnimatedScene s = load(f);
  expectNear(vertexAt(s, 0.5), {0, 0, 0});
  expectNear(vertexAt(s, 1.0), {1, 0, 0});
  expectNear(vertexAt(s, 1.999), {1, 0, 0});  // LINEAR would be at 2.998
  expectNear(vertexAt(s, 2.0), {3, 0, 0});
  EXPECT_EQ(s.animations().at(0).channels.at(0).interpolation, Interpolation::Step);
}

TEST_F(AnimatedSceneTest, LinearLerpsAndClampsOutsideTheKeyframes) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {1, 3}, {0, 0, 0, 2, 4, -6}, "LINEAR");
  const AnimatedScene s = load(f);
  // t = 2.5: s = (2.5 - 1) / (3 - 1) = 0.75 of (2, 4, -6).
  expectNear(vertexAt(s, 2.5), {1.5, 3.0, -4.5});
  // glTF: before the first keyframe the first value, after the last the last.
  expectNear(vertexAt(s, 0.2), {0, 0, 0});
  expectNear(vertexAt(s, 10.0), {2, 4, -6});
  EXPECT_DOUBLE_EQ(s.start_s(), 1.0);
  EXPECT_DOUBLE_EQ(s.end_s(), 3.0);
  EXPECT_DOUBLE_EQ(s.animations().at(0).duration_s(), 2.0);
}

TEST_F(AnimatedSceneTest, RotationSlerpsAlongTheShortestArc) {
  AnimatedGltf f;
  // Identity at t = 0; 90 deg about +Z at t = 1, written as the negated
  // quaternion -(0, 0, sin 45, cos 45): the same rotation. Without the sign
  // flip the slerp would go the long way (-135 deg at t = 0.5).
  f.addChannel(0, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, -kS45, -kS45}, "LINEAR");
  const AnimatedScene s = load(f);
  // Slerp turns at a constant rate: t = 0.5 -> 45 deg, t = 0.25 -> 22.5 deg
  // (a normalised lerp would give 2 atan(0.25 sin45 / (0.75 + 0.25 cos45))
  // = 21.6 deg there).
  for (const double t : {0.25, 0.5, 0.75}) {
    const double angle = t * M_PI / 2.0;
    expectNear(vertexAt(s, t, 1), {std::cos(angle), std::sin(angle), 0.0});
  }
  expectNear(vertexAt(s, 1.0, 1), {0, 1, 0});
}

TEST_F(AnimatedSceneTest, CubicSplineIsHermiteWithTangentsTimesTheInterval) {
  AnimatedGltf f;
  // Keyframes at t = 0 and 2 (interval 2 s): (in, value, out) triplets.
  // k0: value 0, out-tangent (1, 0, 0) per s; k1: in-tangent (0, 2, 0) per
  // s, value (1, 0, 0).
  f.addChannel(0, "translation", {0, 2},
               {0, 0, 0, /**/ 0, 0, 0, /**/ 1, 0, 0, /**/ 0, 2, 0, /**/ 1, 0, 0, /**/ 0, 0, 0},
               "CUBICSPLINE");
  const AnimatedScene s = load(f);
  // t = 0.5: s = 0.25; Hermite basis h00 = 2s^3 - 3s^2 + 1 = 0.84375,
  // h10 = s^3 - 2s^2 + s = 0.140625, h01 = -2s^3 + 3s^2 = 0.15625,
  // h11 = s^3 - s^2 = -0.046875. p = h00 v0 + h10 (2 out0) + h01 v1 + h11 (2 in1):
  // x = 0.140625 * 2 + 0.15625 = 0.4375 (unscaled tangents: 0.296875),
  // y = -0.046875 * 2 * 2 = -0.1875 (unscaled: -0.09375).
  expectNear(vertexAt(s, 0.5), {0.4375, -0.1875, 0.0});
  // Clamped: the keyframes' values, not their tangents.
  expectNear(vertexAt(s, -1.0), {0, 0, 0});
  expectNear(vertexAt(s, 5.0), {1, 0, 0});
  expectNear(vertexAt(s, 2.0), {1, 0, 0});
}

TEST_F(AnimatedSceneTest, CubicSplineRotationIsNormalised) {
  AnimatedGltf f;
  // Identity to 90 deg about +Z, zero tangents: at s = 0.5, h00 = h01 = 0.5,
  // p = (0, 0, 0.354, 0.854), length 0.924: a rotation only once normalised,
  // then 45 deg (p is parallel to the half-way quaternion).
  f.addChannel(0, "rotation", {0, 1},
               {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, /**/ 0, 0, 0, 0, 0, 0, kS45, kS45, 0, 0, 0, 0},
               "CUBICSPLINE");
  const AnimatedScene s = load(f);
  expectNear(vertexAt(s, 0.5, 1), {std::cos(M_PI / 4), std::sin(M_PI / 4), 0.0});
}

TEST_F(AnimatedSceneTest, AnimatedCameraNodeMovesAndTurnsTheCamera) {
  AnimatedGltf f;
  f.addChannel(1, "translation", {0, 2}, {0, 0, 5, 4, 0, 5}, "LINEAR");
  // Camera turns 90 deg about +Y: it looks down -Z, then down -X.
  f.addChannel(1, "rotation", {0, 2}, {0, 0, 0, 1, 0, kS45, 0, kS45}, "LINEAR");
  const AnimatedScene s = load(f, R"([{"mesh": 0}, {"camera": 0, "name": "cam"}])", "[0, 1]",
                               R"(, "cameras": [{"type": "perspective",
                                  "perspective": {"yfov": 0.8, "znear": 0.1}}])");
  ASSERT_EQ(s.movingCameras(), std::vector<std::size_t>{0});
  EXPECT_TRUE(s.movingMeshes().empty());
  const Scene at1 = s.sceneAt(1.0);
  expectNear(glm::dvec3(at1.cameras.at(0).position_world), {2, 0, 5});
  // Half-way: 45 deg about +Y turns -Z into (-sin45, 0, -cos45).
  expectNear(glm::dvec3(at1.cameras.at(0).forward_world), {-std::sqrt(0.5), 0, -std::sqrt(0.5)});
  expectNear(glm::dvec3(s.sceneAt(2.0).cameras.at(0).forward_world), {-1, 0, 0});
  EXPECT_EQ(at1.cameras.at(0).fov_y_deg, s.restScene().cameras.at(0).fov_y_deg);
}

TEST_F(AnimatedSceneTest, ParentAnimationMovesItsChildMeshOnly) {
  AnimatedGltf f;
  // Node 0 (no mesh) turns 0 -> 90 deg about +Z; its child node 1 holds the
  // triangle 1 m along +X; node 2, a sibling root, holds it too and is static.
  f.addChannel(0, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, kS45, kS45}, "LINEAR");
  const AnimatedScene s = load(
      f, R"([{"children": [1]}, {"mesh": 0, "translation": [1, 0, 0]}, {"mesh": 0}])", "[0, 2]");
  ASSERT_EQ(s.movingMeshes(), std::vector<std::size_t>{0});
  // World = parent(t) x child: vertex (0,0,0) -> R (1,0,0) = (0,1,0) at t = 1;
  // the other order (child x parent) would leave it at (1,0,0).
  expectNear(vertexAt(s, 1.0, 0), {0, 1, 0});
  expectNear(vertexAt(s, 1.0, 1), {0, 2, 0});
  expectNear(vertexAt(s, 0.5, 1), {2 * std::sqrt(0.5), 2 * std::sqrt(0.5), 0});
  const glm::dmat4 world = s.meshTransformsAt(1.0).at(0);
  expectNear(glm::dvec3(world * glm::dvec4(1, 0, 0, 1)), {0, 2, 0});
  // The static sibling keeps its bytes.
  const Scene at1 = s.sceneAt(1.0);
  EXPECT_EQ(at1.meshes.at(1).positions_world, s.restScene().meshes.at(1).positions_world);
  // Rotated normals stay the triangle's: +Z.
  expectNear(glm::dvec3(at1.meshes.at(0).normals_world.at(0)), {0, 0, 1});
}

// Byte-for-byte equality of two scenes' geometry and cameras.
void expectSameBytes(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t m = 0; m < a.meshes.size(); ++m) {
    const Mesh& x = a.meshes[m];
    const Mesh& y = b.meshes[m];
    ASSERT_EQ(x.positions_world.size(), y.positions_world.size());
    ASSERT_EQ(x.normals_world.size(), y.normals_world.size());
    EXPECT_EQ(0, std::memcmp(x.positions_world.data(), y.positions_world.data(),
                             x.positions_world.size() * sizeof(glm::vec3)));
    EXPECT_EQ(0, std::memcmp(x.normals_world.data(), y.normals_world.data(),
                             x.normals_world.size() * sizeof(glm::vec3)));
    EXPECT_EQ(x.indices, y.indices);
    EXPECT_EQ(x.material, y.material);
  }
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (std::size_t c = 0; c < a.cameras.size(); ++c) {
    EXPECT_EQ(0, std::memcmp(&a.cameras[c].position_world, &b.cameras[c].position_world,
                             sizeof(glm::vec3)));
    EXPECT_EQ(0, std::memcmp(&a.cameras[c].forward_world, &b.cameras[c].forward_world,
                             sizeof(glm::vec3)));
    EXPECT_EQ(0, std::memcmp(&a.cameras[c].up_world, &b.cameras[c].up_world, sizeof(glm::vec3)));
  }
}

// The float sin 45 deg written out exactly (17 digits), so that the file's
// node rotation and a float keyframe hold the same number; that quaternion's
// length is not exactly 1, so normalising it would change its bits.
std::string exactS45() {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", static_cast<double>(kS45));
  return text;
}

// A node with all of T, R and S under a parent with its own.
std::string posedNodes() {
  return R"([{"children": [1], "translation": [0.5, 0.25, -1], "scale": [2, 0.5, 4]},
        {"mesh": 0, "translation": [0.75, -2, 3], "rotation": [0, )" +
         exactS45() + ", 0, " + exactS45() + R"(], "scale": [1.5, 2, 0.25]}])";
}

TEST_F(AnimatedSceneTest, SceneWithoutAnimationsIsLoadGltfsByteForByte) {
  const AnimatedScene s = load(AnimatedGltf(), posedNodes());
  EXPECT_FALSE(s.animated());
  const Scene reference = loadGltf(path_);
  expectSameBytes(s.restScene(), reference);
  expectSameBytes(s.sceneAt(0.7), reference);
}

TEST_F(AnimatedSceneTest, ConstantAnimationsKeepTheStaticBytes) {
  AnimatedGltf f;
  // Each mode holding the node's own values (CUBICSPLINE with zero tangents).
  f.addChannel(1, "translation", {0, 1}, {0.75f, -2, 3, 0.75f, -2, 3}, "LINEAR");
  f.addChannel(1, "rotation", {0, 1}, {0, kS45, 0, kS45, 0, kS45, 0, kS45}, "LINEAR");
  f.addChannel(1, "scale", {0, 1},
               {0, 0, 0, 1.5, 2, 0.25, 0, 0, 0, /**/ 0, 0, 0, 1.5, 2, 0.25, 0, 0, 0},
               "CUBICSPLINE");
  f.addChannel(0, "scale", {0, 1}, {2, 0.5, 4, 2, 0.5, 4}, "STEP");
  const AnimatedScene s = load(f, posedNodes());
  ASSERT_TRUE(s.animated());
  const Scene reference = loadGltf(path_);
  expectSameBytes(s.restScene(), reference);
  for (const double t : {0.0, 0.3, 1.0, 4.0}) expectSameBytes(s.sceneAt(t), reference);
  // A moving version of the same file does move (the comparison can fail).
  AnimatedGltf moving;
  moving.addChannel(1, "translation", {0, 1}, {0.75f, -2, 3, 1.75f, -2, 3}, "LINEAR");
  const AnimatedScene m = load(moving, posedNodes());
  EXPECT_NE(m.sceneAt(0.5).meshes.at(0).positions_world,
            loadGltf(path_).meshes.at(0).positions_world);
}

TEST_F(AnimatedSceneTest, UpdateSceneRebakesOnlyWhatMoves) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1}, {0, 0, 0, 0, 0, 1}, "LINEAR");
  const AnimatedScene s =
      load(f, R"([{"mesh": 0}, {"mesh": 0, "translation": [5, 0, 0]}])", "[0, 1]");
  Scene scene = s.restScene();
  s.updateScene(scene, 0.5);
  expectNear(glm::dvec3(scene.meshes.at(0).positions_world.at(0)), {0, 0, 0.5});
  s.updateScene(scene, 1.0);
  expectNear(glm::dvec3(scene.meshes.at(0).positions_world.at(0)), {0, 0, 1});
  expectSameBytes(scene, s.sceneAt(1.0));
}

TEST_F(AnimatedSceneTest, MeshScaledUpFromZeroKeepsItsSlot) {
  AnimatedGltf f;
  f.addChannel(0, "scale", {0, 1}, {0, 0, 0, 1, 1, 1}, "LINEAR");
  const AnimatedScene s = load(f, R"([{"mesh": 0, "scale": [0, 0, 0]}])");
  // loadGltf drops the zero-area triangle; the animated scene keeps an empty
  // slot for it, so Scene::meshes has the same slots at every time.
  EXPECT_TRUE(loadGltf(path_).meshes.empty());
  ASSERT_EQ(s.restScene().meshes.size(), 1u);
  EXPECT_EQ(s.restScene().meshes[0].triangleCount(), 0u);
  EXPECT_EQ(s.sceneAt(0.0).meshes.at(0).triangleCount(), 0u);
  EXPECT_EQ(s.sceneAt(1.0).meshes.at(0).triangleCount(), 1u);
  expectNear(vertexAt(s, 0.5, 1), {0.5, 0, 0});
}

TEST_F(AnimatedSceneTest, MorphWeightsAndSkinsAreCountedAsIgnored) {
  AnimatedGltf f;
  f.addChannel(0, "weights", {0, 1}, {0, 1}, "LINEAR");
  path_ = writeText(dir_ / "anim.gltf", f.json(R"([{"mesh": 0, "skin": 0}])", "[0]",
                                               R"(, "skins": [{"joints": [0]}])"));
  LoadReport report;
  const AnimatedScene s = AnimatedScene::load(path_, &report);
  EXPECT_EQ(report.skins, 1u);
  EXPECT_EQ(report.animations, 1u);
  EXPECT_EQ(s.animations().at(0).ignoredWeightChannels, 1u);
  EXPECT_TRUE(s.animations().at(0).channels.empty());
  EXPECT_FALSE(s.animated());
}

// --- bad input: each a located error (file, animation, channel or sampler) --

void expectLocated(const std::string& error, const std::string& part, const std::string& text) {
  EXPECT_NE(error.find("anim.gltf"), std::string::npos) << error;
  EXPECT_NE(error.find("animation[0]." + part + " 'anim'"), std::string::npos) << error;
  EXPECT_NE(error.find(text), std::string::npos) << error;
}

TEST_F(AnimatedSceneTest, InputNotStrictlyIncreasingIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "LINEAR");
  expectLocated(errorOf(f), "samplers[0]", "not strictly increasing");
}

TEST_F(AnimatedSceneTest, NegativeTimeIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {-0.5, 1}, {0, 0, 0, 1, 0, 0}, "LINEAR");
  expectLocated(errorOf(f), "samplers[0]", "is negative");
}

TEST_F(AnimatedSceneTest, OutputCountNotMatchingInputIsALocatedError) {
  AnimatedGltf linear;
  linear.addChannel(0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "LINEAR");
  expectLocated(errorOf(linear), "samplers[0]", "3 values for 2 input times (LINEAR needs 2)");
  AnimatedGltf cubic;  // two values: right for LINEAR, a third of what CUBICSPLINE needs
  cubic.addChannel(0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "CUBICSPLINE");
  expectLocated(errorOf(cubic), "samplers[0]", "2 values for 2 input times (CUBICSPLINE needs 6)");
}

TEST_F(AnimatedSceneTest, UnknownInterpolationIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "QUADRATIC");
  expectLocated(errorOf(f), "samplers[0]", "unknown interpolation 'QUADRATIC'");
}

TEST_F(AnimatedSceneTest, ChannelTargetingAMissingNodeIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "LINEAR");
  f.addChannel(7, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "LINEAR");
  expectLocated(errorOf(f), "channels[1]", "target node 7 does not exist (1 nodes)");
}

TEST_F(AnimatedSceneTest, AccessorsOfTheWrongTypeAreLocatedErrors) {
  AnimatedGltf vec4Translation;
  const int times = vec4Translation.addFloats({0, 1}, "SCALAR");
  const int quats = vec4Translation.addFloats({0, 0, 0, 1, 0, 0, 0, 1}, "VEC4");
  vec4Translation.addRawChannel(0, "translation", times, quats, "LINEAR");
  expectLocated(errorOf(vec4Translation), "samplers[0]", "must be float VEC3 for translation");

  AnimatedGltf vec3Times;
  const int vecTimes = vec3Times.addFloats({0, 0, 0, 1, 1, 1}, "VEC3");
  const int values = vec3Times.addFloats({0, 0, 0, 1, 0, 0}, "VEC3");
  vec3Times.addRawChannel(0, "scale", vecTimes, values, "LINEAR");
  expectLocated(errorOf(vec3Times), "samplers[0]", "must be float SCALAR times");

  AnimatedGltf vec3Rotation;
  const int t = vec3Rotation.addFloats({0, 1}, "SCALAR");
  const int v = vec3Rotation.addFloats({0, 0, 0, 1, 0, 0}, "VEC3");
  vec3Rotation.addRawChannel(0, "rotation", t, v, "LINEAR");
  expectLocated(errorOf(vec3Rotation), "samplers[0]", "must be VEC4");
}

TEST_F(AnimatedSceneTest, AnimatedNodeWithAMatrixIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "LINEAR");
  expectLocated(errorOf(f, R"([{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"),
                "channels[0]", "has a matrix");
}

// Issue 39: keyframes that carry the scene past what float positions and the
// tracers hold (Embree asserted mid-sequence on a translation of 1e30) are
// refused at load, naming the channel and the keyframe.
TEST_F(AnimatedSceneTest, KeyframeBeyondTheSceneBoundIsALocatedError) {
  AnimatedGltf translation;
  translation.addChannel(0, "translation", {0, 1, 2}, {0, 0, 0, 1, 0, 0, 1e30f, 0, 0}, "LINEAR");
  const std::string t = errorOf(translation);
  expectLocated(t, "channels[0]", "keyframe 2 (translation at 2 s) puts mesh[0] (node 0)");
  EXPECT_NE(t.find("1e+30 m from the origin (at most 1e+06 m)"), std::string::npos) << t;

  AnimatedGltf scale;
  scale.addChannel(0, "scale", {0, 1}, {1, 1, 1, 1e30f, 1e30f, 1e30f}, "STEP");
  expectLocated(errorOf(scale), "channels[0]", "keyframe 1 (scale at 1 s)");

  // A parent's keyframe moves the child's mesh: the parent's channel is named.
  AnimatedGltf parent;
  parent.addChannel(0, "translation", {0, 1}, {0, 0, 0, 0, -2e6f, 0}, "LINEAR");
  expectLocated(errorOf(parent, R"([{"children": [1]}, {"mesh": 0}])"), "channels[0]",
                "keyframe 1 (translation at 1 s) puts mesh[0] (node 1)");
}

// Keyframes in bound, but a cubic tangent of 1e30 m/s throws the segment
// between them out: its middle is checked too, in its first keyframe's name.
TEST_F(AnimatedSceneTest, CubicSegmentOvershootIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1},
               {0, 0, 0, 0, 0, 0, 1e30f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "CUBICSPLINE");
  expectLocated(errorOf(f), "channels[0]", "keyframe 0 (translation at 0.5 s)");
}

// The bound itself is within reach: a scene 1000 km across still loads.
TEST_F(AnimatedSceneTest, KeyframesWithinTheSceneBoundLoad) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1}, {0, 0, 0, 9e5f, 0, 0}, "LINEAR");
  EXPECT_EQ(errorOf(f), "(no error)");
}

// A zero quaternion is no rotation at all (glTF asks for unit ones).
TEST_F(AnimatedSceneTest, ZeroQuaternionKeyframeIsALocatedError) {
  AnimatedGltf f;
  f.addChannel(0, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, 0, 0}, "LINEAR");
  expectLocated(errorOf(f), "samplers[0]", "output keyframe 1 is the zero quaternion");
  // CUBICSPLINE's zero tangents are fine; its zero value is not.
  AnimatedGltf cubic;
  cubic.addChannel(0, "rotation", {0, 1}, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0,  //
                                           0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0},
                   "CUBICSPLINE");
  EXPECT_EQ(errorOf(cubic), "(no error)");
}

}  // namespace
}  // namespace tofsim::scene
