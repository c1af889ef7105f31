#pragma once
// Equiangular sampling of a point on a ray segment towards a point light
// (Kulla and Fajardo 2012, "Importance Sampling Techniques for Path Tracing
// in Participating Media"): t is drawn with density proportional to
// 1 / d(t)^2, d(t) the distance from the ray point to the light, so the
// light's 1 / d^2 cancels in the estimate of the light a medium point
// scatters. Free-flight sampling alone connects points arbitrarily close to
// a point light with weights ~ 1 / d^2: an estimator of infinite variance
// (its mean is right, its noise a few huge samples).

#include <cmath>

#include <glm/glm.hpp>

namespace tofsim::reference {

class Equiangular {
 public:
  /// The segment origin + t direction (unit), t in [0, end) (end may be
  /// infinite), and the light's position.
  Equiangular(const glm::dvec3& origin, const glm::dvec3& direction, double end,
              const glm::dvec3& light) {
    const glm::dvec3 toLight = light - origin;
    delta_ = glm::dot(toLight, direction);
    h_ = glm::length(toLight - delta_ * direction);
    thetaA_ = std::atan2(-delta_, h_);
    thetaB_ = std::isinf(end) ? kHalfPi : std::atan2(end - delta_, h_);
    // A light on the ray's line (a co-located light and camera) leaves no
    // angle to sample over: the free flights alone estimate that segment.
    usable_ = h_ > 1e-9 && thetaB_ - thetaA_ > 1e-12;
  }

  bool usable() const { return usable_; }
  /// t for a uniform u in [0, 1).
  double sample(double u) const {
    return delta_ + h_ * std::tan(thetaA_ + u * (thetaB_ - thetaA_));
  }
  /// Its density at t in [0, end), 1/m (0 when not usable).
  double pdf(double t) const {
    if (!usable_) return 0.0;
    const double x = t - delta_;
    return h_ / ((thetaB_ - thetaA_) * (h_ * h_ + x * x));
  }

 private:
  static constexpr double kHalfPi = 1.57079632679489661923;
  double delta_ = 0.0;  ///< t of the ray point nearest the light
  double h_ = 0.0;      ///< distance of the light from the ray's line
  double thetaA_ = 0.0, thetaB_ = 0.0;
  bool usable_ = false;
};

}  // namespace tofsim::reference
