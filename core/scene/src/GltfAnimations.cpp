#include "GltfAnimations.h"

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "AccessorReader.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

namespace {

std::optional<AnimatedProperty> propertyOf(const std::string& path) {
  if (path == "translation") return AnimatedProperty::Translation;
  if (path == "rotation") return AnimatedProperty::Rotation;
  if (path == "scale") return AnimatedProperty::Scale;
  return std::nullopt;
}

/// Throws the located errors of one animation: "animation[a] 'name'".
class AnimationErrors {
 public:
  AnimationErrors(const GltfDocument& doc, std::size_t index)
      : file_(doc.file), where_("animation[" + std::to_string(index) + "]") {
    const std::string& name = doc.animations[index].name;
    if (!name.empty()) name_ = " '" + name + "'";
  }
  [[noreturn]] void fail(const std::string& part, const std::string& message) const {
    throw InputError(FileLoc{file_}, where_ + "." + part + name_, message);
  }

 private:
  std::string file_;
  std::string where_;
  std::string name_;
};

Interpolation interpolationOf(const std::string& name, const AnimationErrors& errors,
                              const std::string& part) {
  if (name == "STEP") return Interpolation::Step;
  if (name == "LINEAR" || name.empty()) return Interpolation::Linear;
  if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
  errors.fail(part, "unknown interpolation '" + name + "' (STEP, LINEAR or CUBICSPLINE)");
}

/// The sampler's input: float scalars, finite, >= 0, strictly increasing.
std::vector<double> readTimes(const GltfDocument& doc, int accessor, const AnimationErrors& errors,
                              const std::string& part) {
  if (accessor < 0 || accessor >= static_cast<int>(doc.accessors.size())) {
    errors.fail(part, "input accessor " + std::to_string(accessor) + " does not exist");
  }
  const Accessor& a = doc.accessors[accessor];
  const std::string what = "input accessor[" + std::to_string(accessor) + "]";
  if (a.components != 1 || a.componentType != kFloat) {
    errors.fail(part, what + " must be float SCALAR times");
  }
  std::vector<double> times = readAccessor(doc, accessor, "animation input");
  if (times.empty()) errors.fail(part, what + " has no keyframes");
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string key = "time[" + std::to_string(k) + "] " + std::to_string(times[k]) + " s";
    if (!std::isfinite(times[k])) errors.fail(part, what + " " + key + " is not finite");
    if (times[k] < 0.0) errors.fail(part, what + " " + key + " is negative");
    if (k > 0 && !(times[k] > times[k - 1])) {
      errors.fail(part, what + " is not strictly increasing: " + key + " after time[" +
                            std::to_string(k - 1) + "] " + std::to_string(times[k - 1]) + " s");
    }
  }
  return times;
}

/// The sampler's output for `property`: VEC3 floats for translation and
/// scale, VEC4 floats or normalised integers for rotation (glTF's rule).
std::vector<glm::dvec4> readValues(const GltfDocument& doc, int accessor, AnimatedProperty property,
                                   const AnimationErrors& errors, const std::string& part) {
  if (accessor < 0 || accessor >= static_cast<int>(doc.accessors.size())) {
    errors.fail(part, "output accessor " + std::to_string(accessor) + " does not exist");
  }
  const Accessor& a = doc.accessors[accessor];
  const std::string what = "output accessor[" + std::to_string(accessor) + "]";
  const bool rotation = property == AnimatedProperty::Rotation;
  const int components = rotation ? 4 : 3;
  const bool typeOk =
      a.componentType == kFloat || (rotation && a.normalized && a.componentType != kUnsignedInt);
  if (a.components != components || !typeOk) {
    errors.fail(part, what + " must be " +
                          (rotation ? "VEC4 (float or normalized integer)" : "float VEC3") +
                          " for " + toString(property));
  }
  const std::vector<double> raw = readAccessor(doc, accessor, "animation output");
  std::vector<glm::dvec4> values(a.count);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double* v = raw.data() + i * components;
    values[i] = glm::dvec4(v[0], v[1], v[2], rotation ? v[3] : 0.0);
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) ||
        !std::isfinite(values[i].w)) {
      errors.fail(part, what + " element " + std::to_string(i) + " is not finite");
    }
  }
  return values;
}

/// A rotation keyframe is a unit quaternion (glTF); a zero one is no
/// rotation at all (nothing to normalise), so it is refused. CUBICSPLINE's
/// tangents (the first and last of each triple) may be zero.
void checkRotations(const AnimationChannel& channel, const AnimationErrors& errors,
                    const std::string& part) {
  const bool cubic = channel.interpolation == Interpolation::CubicSpline;
  for (std::size_t k = 0; k < channel.times_s.size(); ++k) {
    const glm::dvec4& q = channel.values[cubic ? 3 * k + 1 : k];
    if (!(glm::length(q) > 1e-6)) {
      errors.fail(part, "output keyframe " + std::to_string(k) + " is the zero quaternion (" +
                            std::to_string(q.x) + ", " + std::to_string(q.y) + ", " +
                            std::to_string(q.z) + ", " + std::to_string(q.w) +
                            "): a rotation is a unit quaternion (x, y, z, w)");
    }
  }
}

Animation readAnimation(const GltfDocument& doc, std::size_t index) {
  const AnimationDesc& desc = doc.animations[index];
  const AnimationErrors errors(doc, index);
  Animation out;
  out.name = desc.name;
  std::set<std::pair<int, AnimatedProperty>> targets;
  for (std::size_t c = 0; c < desc.channels.size(); ++c) {
    const AnimationChannelDesc& ch = desc.channels[c];
    const std::string channelPart = "channels[" + std::to_string(c) + "]";
    if (ch.sampler < 0 || ch.sampler >= static_cast<int>(desc.samplers.size())) {
      errors.fail(channelPart, "sampler " + std::to_string(ch.sampler) + " does not exist (" +
                                   std::to_string(desc.samplers.size()) + " samplers)");
    }
    if (ch.node >= static_cast<int>(doc.nodes.size())) {
      errors.fail(channelPart, "target node " + std::to_string(ch.node) + " does not exist (" +
                                   std::to_string(doc.nodes.size()) + " nodes)");
    }
    const std::optional<AnimatedProperty> property = propertyOf(ch.path);
    if (ch.node < 0 || !property) {
      // glTF: a channel without a node is for extensions; weights animate
      // morph targets, which tofsim does not implement.
      ++(ch.node >= 0 && ch.path == "weights" ? out.ignoredWeightChannels
                                              : out.ignoredOtherChannels);
      continue;
    }
    if (doc.nodes[ch.node].trs.matrix) {
      errors.fail(channelPart, "target node " + std::to_string(ch.node) +
                                   " has a matrix (glTF: an animated node has TRS properties)");
    }
    if (!targets.insert({ch.node, *property}).second) {
      errors.fail(channelPart, "animates node " + std::to_string(ch.node) + " " + ch.path +
                                   " a second time in this animation");
    }
    const AnimationSamplerDesc& sampler = desc.samplers[ch.sampler];
    const std::string samplerPart = "samplers[" + std::to_string(ch.sampler) + "]";
    AnimationChannel channel;
    channel.index = c;
    channel.node = ch.node;
    channel.nodeName = doc.nodes[ch.node].name;
    channel.property = *property;
    channel.interpolation = interpolationOf(sampler.interpolation, errors, samplerPart);
    channel.times_s = readTimes(doc, sampler.input, errors, samplerPart);
    channel.values = readValues(doc, sampler.output, *property, errors, samplerPart);
    const bool cubic = channel.interpolation == Interpolation::CubicSpline;
    const std::size_t expected = channel.times_s.size() * (cubic ? 3 : 1);
    if (channel.values.size() != expected) {
      errors.fail(samplerPart, "output has " + std::to_string(channel.values.size()) +
                                   " values for " + std::to_string(channel.times_s.size()) +
                                   " input times (" + toString(channel.interpolation) + " needs " +
                                   std::to_string(expected) + ")");
    }
    if (channel.property == AnimatedProperty::Rotation) checkRotations(channel, errors, samplerPart);
    out.channels.push_back(std::move(channel));
  }
  return out;
}

}  // namespace

std::vector<Animation> readAnimations(const GltfDocument& doc) {
  std::vector<Animation> out;
  for (std::size_t a = 0; a < doc.animations.size(); ++a) out.push_back(readAnimation(doc, a));
  return out;
}

}  // namespace tofsim::scene::detail
