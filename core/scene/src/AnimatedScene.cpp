#include "tofsim/scene/AnimatedScene.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "AccessorReader.h"
#include "GltfAnimations.h"
#include "LoadedDocument.h"
#include "SceneAssembly.h"
#include "tofsim/scene/SceneBound.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene {

namespace {
constexpr std::size_t kProperties = 3;  // translation, rotation, scale
using NodeChannels = std::array<const AnimationChannel*, kProperties>;
}  // namespace

struct AnimatedScene::State {
  detail::GltfDocument doc;
  detail::SceneAssembly assembly;
  std::vector<Animation> animations;
  /// Per glTF node, the channel that drives each property (nullptr: the node's own).
  std::vector<NodeChannels> channels;
  std::vector<bool> nodeAnimated;   ///< per glTF node
  std::vector<bool> instanceMoves;  ///< per node instance: it or an ancestor is animated
  std::vector<std::size_t> movingMeshes;
  std::vector<std::size_t> movingCameras;

  /// The node's local matrix with its animated properties at t_s.
  glm::dmat4 localAt(int node, double t_s) const {
    detail::NodeTrs trs = doc.nodes[node].trs;
    const NodeChannels& c = channels[node];
    if (c[0]) trs.translation = glm::dvec3(sampleChannel(*c[0], t_s));
    if (c[1]) {
      const glm::dvec4 q = sampleChannel(*c[1], t_s);  // glTF (x, y, z, w)
      trs.rotation = glm::dquat(q.w, q.x, q.y, q.z);
    }
    if (c[2]) trs.scale = glm::dvec3(sampleChannel(*c[2], t_s));
    return detail::localMatrix(trs);
  }

  /// World matrix of every node instance at t_s; the rest pose's bits for
  /// the instances that do not move.
  std::vector<glm::dmat4> instanceWorldsAt(double t_s) const {
    const std::vector<detail::NodeInstance>& instances = assembly.instances;
    std::vector<glm::dmat4> world(instances.size());
    for (std::size_t i = 0; i < instances.size(); ++i) {
      const detail::NodeInstance& inst = instances[i];
      if (!instanceMoves[i]) {
        world[i] = inst.world;
        continue;
      }
      const glm::dmat4 parent = inst.parent >= 0 ? world[inst.parent] : glm::dmat4(1.0);
      const glm::dmat4 local =
          nodeAnimated[inst.node] ? localAt(inst.node, t_s) : doc.nodes[inst.node].local;
      world[i] = parent * local;
    }
    return world;
  }
};

namespace {

/// Which channel drives each node property; a later animation overrides an
/// earlier one on the same property (a warning: glTF leaves it undefined).
std::vector<NodeChannels> driverChannels(const detail::GltfDocument& doc,
                                         const std::vector<Animation>& animations,
                                         LoadReport& report) {
  std::vector<NodeChannels> out(doc.nodes.size(), NodeChannels{});
  for (std::size_t a = 0; a < animations.size(); ++a) {
    for (const AnimationChannel& c : animations[a].channels) {
      const AnimationChannel*& slot = out[c.node][static_cast<std::size_t>(c.property)];
      if (slot) {
        report.warnings.push_back("animation[" + std::to_string(a) + "] overrides node[" +
                                  std::to_string(c.node) + "] " + toString(c.property) +
                                  " of an earlier animation");
      }
      slot = &c;
    }
  }
  return out;
}

/// The 8 corners of the box around a mesh slot's POSITION values (model
/// space): an affine pose maps the box around the vertices onto a
/// parallelepiped around them, so its corners bound the posed vertices.
std::array<glm::dvec3, 8> slotCorners(const detail::GltfDocument& doc,
                                      const detail::MeshSlot& slot) {
  const detail::Primitive& prim =
      doc.meshes[slot.primitive.mesh].primitives[slot.primitive.primitive];
  glm::dvec3 lo(0.0), hi(0.0);
  bool first = true;
  for (const glm::vec3& v : detail::readVec3(doc, prim.position, "POSITION")) {
    lo = first ? glm::dvec3(v) : glm::min(lo, glm::dvec3(v));
    hi = first ? glm::dvec3(v) : glm::max(hi, glm::dvec3(v));
    first = false;
  }
  std::array<glm::dvec3, 8> corners;
  for (int c = 0; c < 8; ++c) {
    corners[c] = glm::dvec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
  }
  return corners;
}

/// Whether `node` is the node of instance i or of one above it.
bool movedBy(const std::vector<detail::NodeInstance>& instances, std::size_t i, int node) {
  for (int k = static_cast<int>(i); k >= 0; k = instances[k].parent) {
    if (instances[k].node == node) return true;
  }
  return false;
}

}  // namespace

void AnimatedScene::checkKeyframeExtents() const {
  const State& s = *state_;
  const std::vector<detail::NodeInstance>& instances = s.assembly.instances;
  std::vector<std::array<glm::dvec3, 8>> corners;
  for (const std::size_t m : s.movingMeshes) {
    corners.push_back(slotCorners(s.doc, s.assembly.meshSlots[m]));
  }
  for (std::size_t a = 0; a < s.animations.size(); ++a) {
    const Animation& animation = s.animations[a];
    for (const AnimationChannel& channel : animation.channels) {
      const auto fail = [&](std::size_t k, double t, const std::string& what,
                            const glm::dvec3& p) {
        const std::string name = animation.name.empty() ? "" : " '" + animation.name + "'";
        char time[48];
        std::snprintf(time, sizeof time, "%.6g s", t);
        throw InputError(FileLoc{s.doc.file},
                         "animation[" + std::to_string(a) + "].channels[" +
                             std::to_string(channel.index) + "]" + name,
                         "keyframe " + std::to_string(k) + " (" + toString(channel.property) +
                             " at " + time + ") puts " + what + " " + sceneBoundText(p));
      };
      // What this channel moves (the poses of the rest are not its doing).
      std::vector<std::size_t> meshes, cameras;
      for (std::size_t i = 0; i < s.movingMeshes.size(); ++i) {
        const std::size_t inst = s.assembly.meshSlots[s.movingMeshes[i]].instance;
        if (movedBy(instances, inst, channel.node)) meshes.push_back(i);
      }
      for (const std::size_t c : s.movingCameras) {
        const std::size_t inst = s.assembly.cameraSlots[c].instance;
        if (movedBy(instances, inst, channel.node)) cameras.push_back(inst);
      }
      if (meshes.empty() && cameras.empty()) continue;
      // CUBICSPLINE's tangents can carry a segment past both its keyframes:
      // its middles too, in the name of the keyframe that starts it.
      const bool cubic = channel.interpolation == Interpolation::CubicSpline;
      const std::size_t n = channel.times_s.size();
      for (std::size_t j = 0; j < (cubic ? 2 * n - 1 : n); ++j) {
        const std::size_t k = cubic ? j / 2 : j;
        const double t = cubic && j % 2 ? 0.5 * (channel.times_s[k] + channel.times_s[k + 1])
                                        : channel.times_s[k];
        const std::vector<glm::dmat4> world = s.instanceWorldsAt(t);
        for (const std::size_t i : meshes) {
          const detail::MeshSlot& slot = s.assembly.meshSlots[s.movingMeshes[i]];
          for (const glm::dvec3& corner : corners[i]) {
            const glm::dvec3 p(world[slot.instance] * glm::dvec4(corner, 1.0));
            if (!withinSceneBound(p)) {
              fail(k, t, "mesh[" + std::to_string(slot.primitive.mesh) + "] (node " +
                             std::to_string(instances[slot.instance].node) + ")", p);
            }
          }
        }
        for (const std::size_t inst : cameras) {
          const glm::dvec3 p(world[inst][3]);
          if (!withinSceneBound(p)) {
            fail(k, t, "the camera of node " + std::to_string(instances[inst].node), p);
          }
        }
      }
    }
  }
}

AnimatedScene::AnimatedScene(std::unique_ptr<State> state) : state_(std::move(state)) {}
AnimatedScene::AnimatedScene(AnimatedScene&&) noexcept = default;
AnimatedScene& AnimatedScene::operator=(AnimatedScene&&) noexcept = default;
AnimatedScene::~AnimatedScene() = default;

AnimatedScene AnimatedScene::load(const std::filesystem::path& path, LoadReport* reportOut) {
  auto state = std::make_unique<State>();
  State& s = *state;
  s.doc = detail::loadDocument(path);
  s.animations = detail::readAnimations(s.doc);
  LoadReport report;
  s.channels = driverChannels(s.doc, s.animations, report);
  s.nodeAnimated.assign(s.doc.nodes.size(), false);
  for (std::size_t n = 0; n < s.doc.nodes.size(); ++n) {
    const NodeChannels& c = s.channels[n];
    s.nodeAnimated[n] = std::any_of(c.begin(), c.end(), [](const auto* p) { return p; });
  }
  // The instances as flattenNodes lists them (the assembly flattens the same
  // way), so that their parents are known before the scene is baked.
  const std::vector<detail::NodeInstance> instances = detail::flattenNodes(s.doc);
  s.instanceMoves.assign(instances.size(), false);
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const int parent = instances[i].parent;
    s.instanceMoves[i] =
        s.nodeAnimated[instances[i].node] || (parent >= 0 && s.instanceMoves[parent]);
  }
  s.assembly = detail::assembleScene(s.doc, report, s.instanceMoves);
  detail::reportIgnoredAnimationParts(s.doc, report);
  for (std::size_t m = 0; m < s.assembly.meshSlots.size(); ++m) {
    if (s.instanceMoves[s.assembly.meshSlots[m].instance]) s.movingMeshes.push_back(m);
  }
  for (std::size_t c = 0; c < s.assembly.cameraSlots.size(); ++c) {
    if (s.instanceMoves[s.assembly.cameraSlots[c].instance]) s.movingCameras.push_back(c);
  }
  AnimatedScene scene(std::move(state));
  scene.checkKeyframeExtents();
  if (reportOut) *reportOut = std::move(report);
  return scene;
}

const Scene& AnimatedScene::restScene() const { return state_->assembly.scene; }
const std::vector<Animation>& AnimatedScene::animations() const { return state_->animations; }
bool AnimatedScene::animated() const {
  return !state_->movingMeshes.empty() || !state_->movingCameras.empty();
}

double AnimatedScene::start_s() const {
  std::optional<double> t;
  for (const Animation& a : state_->animations) {
    if (!a.channels.empty()) t = std::min(t.value_or(a.start_s()), a.start_s());
  }
  return t.value_or(0.0);
}

double AnimatedScene::end_s() const {
  double t = 0.0;
  for (const Animation& a : state_->animations) t = std::max(t, a.end_s());
  return t;
}

const std::vector<std::size_t>& AnimatedScene::movingMeshes() const { return state_->movingMeshes; }
const std::vector<std::size_t>& AnimatedScene::movingCameras() const {
  return state_->movingCameras;
}

std::vector<glm::dmat4> AnimatedScene::meshTransformsAt(double t_s) const {
  const std::vector<glm::dmat4> world = state_->instanceWorldsAt(t_s);
  std::vector<glm::dmat4> out;
  for (const detail::MeshSlot& slot : state_->assembly.meshSlots)
    out.push_back(world[slot.instance]);
  return out;
}

Scene AnimatedScene::sceneAt(double t_s) const {
  Scene scene = restScene();
  updateScene(scene, t_s);
  return scene;
}

void AnimatedScene::updateScene(Scene& scene, double t_s) const {
  const State& s = *state_;
  const Scene& rest = s.assembly.scene;
  TOFSIM_CHECK_EQ(scene.meshes.size(), rest.meshes.size());
  TOFSIM_CHECK_EQ(scene.cameras.size(), rest.cameras.size());
  if (!animated()) return;
  const std::vector<glm::dmat4> world = s.instanceWorldsAt(t_s);
  for (const std::size_t m : s.movingMeshes) {
    const detail::MeshSlot& slot = s.assembly.meshSlots[m];
    scene.meshes[m] = detail::rebakeMesh(s.doc, slot, rest.meshes[m], world[slot.instance]);
  }
  for (const std::size_t c : s.movingCameras) {
    const detail::CameraSlot& slot = s.assembly.cameraSlots[c];
    scene.cameras[c] = detail::placeCamera(s.doc, slot, s.assembly.instances[slot.instance].node,
                                           world[slot.instance]);
  }
}

}  // namespace tofsim::scene
