#pragma once
// glTF 2.0 node animations: keyframed translation, rotation and scale of a
// node, sampled at a time in seconds of scene time (glTF's unit).
//
// Interpolation follows the glTF 2.0 specification (Appendix C): STEP holds
// a keyframe until the next, LINEAR lerps vectors and slerps rotations along
// the shortest arc, CUBICSPLINE is a Hermite spline whose tangents are scaled
// by the keyframe interval. Interpolated rotations are normalised. Before the
// first keyframe and after the last, the channel holds that keyframe's value.

#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tofsim::scene {

enum class Interpolation { Step, Linear, CubicSpline };

/// The node property a channel animates.
enum class AnimatedProperty { Translation, Rotation, Scale };

const char* toString(Interpolation interpolation);  ///< glTF's name: "STEP", ...
const char* toString(AnimatedProperty property);    ///< glTF's path: "translation", ...

/// One animated property of one node, with its sampler's keyframes.
struct AnimationChannel {
  std::size_t index = 0;  ///< its place in the glTF animation's `channels` (for errors)
  int node = -1;          ///< glTF node index
  std::string nodeName;  ///< its name, empty if unnamed
  AnimatedProperty property = AnimatedProperty::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<double> times_s;  ///< keyframe times, s, >= 0 and strictly increasing
  /// Per keyframe one value (three for CUBICSPLINE: in-tangent, value,
  /// out-tangent; tangents in units per second). Translation (m) and scale in
  /// xyz (w = 0); rotation as glTF's quaternion (x, y, z, w).
  std::vector<glm::dvec4> values;

  std::size_t keyframeCount() const { return times_s.size(); }
};

struct Animation {
  std::string name;
  std::vector<AnimationChannel> channels;  ///< translation, rotation and scale channels
  std::size_t ignoredWeightChannels = 0;   ///< morph-target "weights" channels (not played)
  std::size_t ignoredOtherChannels = 0;    ///< channels without a target node or with another path

  double start_s() const;  ///< first keyframe over all channels; 0 without channels
  double end_s() const;    ///< last keyframe over all channels; 0 without channels
  double duration_s() const { return end_s() - start_s(); }
};

/// The channel's value at time t_s (see the top of this file); at a keyframe
/// time, and on a segment whose two keyframes hold the same value (and zero
/// tangents), the file's value exactly.
glm::dvec4 sampleChannel(const AnimationChannel& channel, double t_s);

}  // namespace tofsim::scene
