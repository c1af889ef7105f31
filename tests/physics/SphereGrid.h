#pragma once
// A (s, phi) grid over the whole sphere of directions, refined around an
// axis: cos(angle to axis) = 1 - 2 s^4 for s in [0, 1], so dw = 8 s^3 ds dphi
// and the angle to the axis grows as 2 s^2 near it: a narrow lobe around the
// axis (a GGX peak of width ~alpha) gets many cells. Used for quadrature of
// densities and BRDFs and for binning sampled directions (chi-square tests).

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "tofsim/physics/HemisphereSampling.h"

namespace tofsim::test {

class SphereGrid {
 public:
  static constexpr double kPi = 3.14159265358979323846;

  SphereGrid(const glm::vec3& axis, int cellsS, int cellsPhi)
      : axis_(glm::normalize(axis)), cellsS_(cellsS), cellsPhi_(cellsPhi) {
    physics::orthonormalBasis(axis_, t_, b_);
  }

  int cells() const { return cellsS_ * cellsPhi_; }

  /// Direction at grid coordinates (s, phi), s in [0, 1], phi in [0, 2 pi).
  glm::vec3 direction(double s, double phi) const {
    const double cosA = 1.0 - 2.0 * s * s * s * s;
    const double sinA = std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
    return glm::normalize(glm::vec3(glm::dvec3(t_) * (sinA * std::cos(phi)) +
                                    glm::dvec3(b_) * (sinA * std::sin(phi)) +
                                    glm::dvec3(axis_) * cosA));
  }

  /// The cell a unit direction falls in.
  int cellOf(const glm::vec3& w) const {
    const double cosA = std::clamp(static_cast<double>(glm::dot(w, axis_)), -1.0, 1.0);
    const double s = std::sqrt(std::sqrt(std::max(0.0, (1.0 - cosA) / 2.0)));
    double phi = std::atan2(glm::dot(w, b_), glm::dot(w, t_));
    if (phi < 0.0) phi += 2.0 * kPi;
    const int is = std::min(cellsS_ - 1, static_cast<int>(s * cellsS_));
    const int ip = std::min(cellsPhi_ - 1, static_cast<int>(phi / (2.0 * kPi) * cellsPhi_));
    return is * cellsPhi_ + ip;
  }

  /// Integral of g(w) over one cell by a sub x sub midpoint rule.
  template <class G>
  double integrateCell(int cell, int sub, G&& g) const {
    const int is = cell / cellsPhi_, ip = cell % cellsPhi_;
    const double ds = 1.0 / (cellsS_ * sub), dphi = 2.0 * kPi / (cellsPhi_ * sub);
    double sum = 0.0;
    for (int i = 0; i < sub; ++i) {
      const double s = (is * sub + i + 0.5) * ds;
      for (int j = 0; j < sub; ++j) {
        const double phi = (ip * sub + j + 0.5) * dphi;
        sum += g(direction(s, phi)) * 8.0 * s * s * s * ds * dphi;
      }
    }
    return sum;
  }

  /// Integral of g(w) over the sphere.
  template <class G>
  double integrate(int sub, G&& g) const {
    double sum = 0.0;
    for (int c = 0; c < cells(); ++c) sum += integrateCell(c, sub, g);
    return sum;
  }

 private:
  glm::vec3 axis_, t_, b_;
  int cellsS_, cellsPhi_;
};

}  // namespace tofsim::test
