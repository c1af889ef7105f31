#pragma once
// Equiangular sampling of a point on a ray segment towards a point light
// (Kulla and Fajardo 2012, "Importance Sampling Techniques for Path Tracing
// in Participating Media"), weighted by the phase function: the light a
// medium point at t scatters along the ray is
//   sigma_s T(t) p(theta) I T(d) / d^2 dt = sigma_s T T I p(theta) dphi / h,
// phi the angle of the point seen from the light, measured from the ray's
// nearest point to it (t = delta + h tan phi, d = h / cos phi), and theta
// the scattering angle, theta = phi + pi/2 (cos theta = -sin phi). Drawing
// phi with density proportional to p(theta) (a table over theta, piecewise
// constant, restricted to the segment's angles) leaves only the
// transmittances to vary: the 1 / d^2 of a point light and a forward-peaked
// phase function (fog's g ~ 0.85, whose forward lobe sits where a ray aims
// at the light) both cancel. Isotropic: plain equiangular sampling.
// Free-flight sampling alone connects points arbitrarily close to a point
// light with weights ~ 1 / d^2, an estimator of infinite variance.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::reference {

/// The density of the scattering angle theta in [0, pi] proportional to the
/// phase function p(cos theta) (per radian, not per steradian): kCells
/// cells of constant density, built once per medium.
class PhaseAngleTable {
 public:
  static constexpr int kCells = 2048;
  static constexpr double kPi = 3.14159265358979323846;

  PhaseAngleTable(int32_t model, float g) : cdf_(kCells + 1, 0.0), density_(kCells, 0.0) {
    const double width = kPi / kCells;
    for (int i = 0; i < kCells; ++i) {
      const double theta = (i + 0.5) * width;
      density_[static_cast<std::size_t>(i)] =
          std::max(1e-12, static_cast<double>(physics::phaseFunction(
                              model, g, static_cast<float>(std::cos(theta)))));
      cdf_[static_cast<std::size_t>(i) + 1] = cdf_[static_cast<std::size_t>(i)] +
                                              density_[static_cast<std::size_t>(i)] * width;
    }
    const double total = cdf_.back();
    for (double& c : cdf_) c /= total;
    for (double& d : density_) d /= total;
    cdf_.back() = 1.0;
  }

  /// Density at theta (1/rad), and the cumulative probability up to theta.
  double density(double theta) const { return density_[cell(theta)]; }
  double cdf(double theta) const {
    const std::size_t i = cell(theta);
    return cdf_[i] + density_[i] * (theta - static_cast<double>(i) * kPi / kCells);
  }
  /// The theta whose cumulative probability is c.
  double inverse(double c) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), c);
    const std::size_t i = std::min<std::size_t>(
        kCells - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - cdf_.begin() - 1)));
    return static_cast<double>(i) * kPi / kCells + (c - cdf_[i]) / density_[i];
  }

 private:
  std::size_t cell(double theta) const {
    const double x = theta / kPi * kCells;
    return static_cast<std::size_t>(std::clamp(x, 0.0, static_cast<double>(kCells - 1)));
  }
  std::vector<double> cdf_;
  std::vector<double> density_;
};

class Equiangular {
 public:
  /// The segment origin + t direction (unit), t in [0, end) (end may be
  /// infinite), the light's position, the medium's angle table.
  Equiangular(const glm::dvec3& origin, const glm::dvec3& direction, double end,
              const glm::dvec3& light, const PhaseAngleTable& table)
      : table_(table) {
    const glm::dvec3 toLight = light - origin;
    delta_ = glm::dot(toLight, direction);
    h_ = glm::length(toLight - delta_ * direction);
    // theta = phi + pi/2, phi from atan(-delta / h) (t = 0) to atan((end - delta) / h).
    thetaA_ = std::atan2(-delta_, h_) + kHalfPi;
    thetaB_ = std::isinf(end) ? 2.0 * kHalfPi : std::atan2(end - delta_, h_) + kHalfPi;
    cdfA_ = table_.cdf(thetaA_);
    mass_ = table_.cdf(thetaB_) - cdfA_;
    // A light on the ray's line (a co-located light and camera) leaves no
    // angle to sample over: the free flights alone estimate that segment.
    usable_ = h_ > 1e-9 && thetaB_ - thetaA_ > 1e-12 && mass_ > 0.0;
  }

  bool usable() const { return usable_; }
  /// t for a uniform u in [0, 1).
  double sample(double u) const {
    const double theta = std::clamp(table_.inverse(cdfA_ + u * mass_), thetaA_, thetaB_);
    return delta_ - h_ / std::tan(theta);  // h tan(theta - pi/2)
  }
  /// Its density at t in [0, end), 1/m (0 when not usable).
  double pdf(double t) const {
    if (!usable_) return 0.0;
    const double x = t - delta_;
    const double theta = std::atan2(x, h_) + kHalfPi;
    if (theta < thetaA_ || theta > thetaB_) return 0.0;
    // d theta / dt = h / (h^2 + x^2).
    return table_.density(theta) / mass_ * h_ / (h_ * h_ + x * x);
  }

 private:
  static constexpr double kHalfPi = 1.57079632679489661923;
  const PhaseAngleTable& table_;
  double delta_ = 0.0;  ///< t of the ray point nearest the light
  double h_ = 0.0;      ///< distance of the light from the ray's line
  double thetaA_ = 0.0, thetaB_ = 0.0;  ///< scattering angles at t = 0 and t = end
  double cdfA_ = 0.0, mass_ = 0.0;      ///< the table's probability below thetaA, within
  bool usable_ = false;
};

}  // namespace tofsim::reference
