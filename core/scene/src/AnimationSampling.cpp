#include <algorithm>
#include <cmath>

#include "tofsim/scene/Animation.h"

namespace tofsim::scene {

namespace {

// A rotation keyframe as a unit quaternion's 4-vector, normalised.
glm::dvec4 normalised(const glm::dvec4& q) {
  const double len = glm::length(q);
  return len > 0.0 ? q / len : q;
}

// Shortest-arc spherical interpolation of two unit quaternions (x, y, z, w):
// q and -q are the same rotation, so b is flipped onto a's hemisphere.
glm::dvec4 slerp(const glm::dvec4& a, glm::dvec4 b, double s) {
  double cosTheta = glm::dot(a, b);
  if (cosTheta < 0.0) {
    b = -b;
    cosTheta = -cosTheta;
  }
  // Nearly parallel: sin(theta) -> 0; the normalised lerp is exact to O(theta^3).
  if (cosTheta > 1.0 - 1e-9) return normalised(a + s * (b - a));
  const double theta = std::acos(std::min(cosTheta, 1.0));
  const double sinTheta = std::sin(theta);
  return normalised((std::sin((1.0 - s) * theta) / sinTheta) * a +
                    (std::sin(s * theta) / sinTheta) * b);
}

}  // namespace

const char* toString(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::Step:
      return "STEP";
    case Interpolation::Linear:
      return "LINEAR";
    case Interpolation::CubicSpline:
      return "CUBICSPLINE";
  }
  return "?";
}

const char* toString(AnimatedProperty property) {
  switch (property) {
    case AnimatedProperty::Translation:
      return "translation";
    case AnimatedProperty::Rotation:
      return "rotation";
    case AnimatedProperty::Scale:
      return "scale";
  }
  return "?";
}

double Animation::start_s() const {
  double t = 0.0;
  bool any = false;
  for (const AnimationChannel& c : channels) {
    if (c.times_s.empty()) continue;
    t = any ? std::min(t, c.times_s.front()) : c.times_s.front();
    any = true;
  }
  return t;
}

double Animation::end_s() const {
  double t = 0.0;
  for (const AnimationChannel& c : channels) {
    if (!c.times_s.empty()) t = std::max(t, c.times_s.back());
  }
  return t;
}

glm::dvec4 sampleChannel(const AnimationChannel& c, double t_s) {
  const std::vector<double>& times = c.times_s;
  const bool cubic = c.interpolation == Interpolation::CubicSpline;
  const auto value = [&](std::size_t k) { return c.values[cubic ? 3 * k + 1 : k]; };
  if (times.empty()) return glm::dvec4(0.0);
  // glTF: before the first keyframe and after the last, hold it.
  if (!(t_s > times.front())) return value(0);
  if (t_s >= times.back()) return value(times.size() - 1);
  // times[k] <= t_s < times[k + 1]
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t_s) - times.begin()) -
      1;
  const glm::dvec4 a = value(k);
  const glm::dvec4 b = value(k + 1);
  if (t_s == times[k] || c.interpolation == Interpolation::Step) return a;
  const double interval_s = times[k + 1] - times[k];
  const double s = (t_s - times[k]) / interval_s;
  const bool rotation = c.property == AnimatedProperty::Rotation;
  if (!cubic) {
    if (a == b) return a;  // a held value keeps its bits
    return rotation ? slerp(a, b, s) : a + s * (b - a);
  }
  // Hermite spline (glTF 2.0 Appendix C): the out-tangent of k and the
  // in-tangent of k + 1, both per second, times the interval.
  const glm::dvec4 outTangent = c.values[3 * k + 2] * interval_s;
  const glm::dvec4 inTangent = c.values[3 * (k + 1)] * interval_s;
  if (a == b && outTangent == glm::dvec4(0.0) && inTangent == glm::dvec4(0.0)) return a;
  const double s2 = s * s, s3 = s2 * s;
  const glm::dvec4 p = (2.0 * s3 - 3.0 * s2 + 1.0) * a + (s3 - 2.0 * s2 + s) * outTangent +
                       (-2.0 * s3 + 3.0 * s2) * b + (s3 - s2) * inTangent;
  return rotation ? normalised(p) : p;
}

}  // namespace tofsim::scene
