#pragma once
// Time-domain diffusion closed forms for the reference's multiple-scattering
// tests (issue 42; core/physics/medium_diffusion.md). Lengths in metres,
// time as the geometric path l = c t (c = c0 / eta in the medium): the
// reference bins every path at eta x its geometric length, so a bin is an
// interval of l whatever eta is. Every form is per unit source energy and
// per unit l (a bin is its integral over the bin's l).

#include <cmath>

#include "support/Simpson.h"

namespace tofsim::test::diffusion {

constexpr double kPi = 3.14159265358979323846;

/// The infinite homogeneous medium's Green's function (Patterson, Chance and
/// Wilson 1989, Appl. Opt. 28(12):2331, eq. 2): the fluence c dt-integrated
/// at squared distance r2 from an isotropic unit pulse, per unit l:
/// (4 pi D l)^(-3/2) exp(-r2 / (4 D l) - mu_a l).
inline double green(double r2, double l, double d, double muA) {
  return std::pow(4.0 * kPi * d * l, -1.5) * std::exp(-r2 / (4.0 * d * l) - muA * l);
}

using test::simpson;

/// A semi-infinite medium z > 0 behind an index-matched boundary z = 0 (the
/// light that crosses it never returns), an isotropic unit pulse at depth
/// z0 on the z axis, seen at the boundary point at distance rho from the
/// axis. The fluence is the source's Green's function less that of a
/// negative image at -(z0 + 2 zb), which makes it vanish on the plane
/// z = -zb:
///  - zb = 0: Patterson et al. 1989's zero boundary (their eq. 3): phi = 0
///    on z = 0, and the reflectance is the flux R = D dphi/dz there, with
///    the closed form (4 pi D)^(-3/2) z0 l^(-5/2) exp(-mu_a l) exp(-(rho^2 +
///    z0^2) / (4 D l));
///  - zb = 2 D: the extrapolated boundary of an index-matched interface
///    (Haskell et al. 1994, J. Opt. Soc. Am. A 11(10):2727, zb = 2 A D with
///    A = 1 without a mismatch; Kienle and Patterson 1997, J. Opt. Soc. Am. A
///    14(1):246, compare both with Monte Carlo).
/// D = 1 / (3 mu_s'): in the time domain the diffusion coefficient does not
/// depend on mu_a (Durduran et al. 1997, J. Opt. Soc. Am. A 14(12):3358).
struct SemiInfinite {
  double muA = 0.0, muSPrime = 0.0;  ///< 1/m
  double rho = 0.0;                  ///< source axis to the boundary point, m
  double z0 = 0.0;                   ///< source depth, m
  double zb = 0.0;                   ///< extrapolation distance, m

  double d() const { return 1.0 / (3.0 * muSPrime); }

  /// Fluence at the boundary point (zero with zb = 0) and its derivative into
  /// the medium, d/dz, per unit l.
  double fluence(double l) const {
    const double zi = z0 + 2.0 * zb;
    return green(z0 * z0 + rho * rho, l, d(), muA) - green(zi * zi + rho * rho, l, d(), muA);
  }
  double fluenceSlope(double l) const {
    // d/dz of G((z - zs)^2 + rho^2) at z = 0 is G zs / (2 D l); the image sits at zs = -zi.
    const double zi = z0 + 2.0 * zb;
    return (green(z0 * z0 + rho * rho, l, d(), muA) * z0 +
            green(zi * zi + rho * rho, l, d(), muA) * zi) /
           (2.0 * d() * l);
  }

  /// The radiance at the boundary point travelling out of the medium at
  /// angle theta from the boundary's normal, per unit l, from a source of
  /// intensity 1 (power 4 pi): the P1 radiance (phi + 3 F . s) / (4 pi)
  /// x 4 pi, F . s = D dphi/dz cos theta (the flux along the boundary is
  /// zero at the point's mirror-symmetric pixels' mean).
  double radiance(double l, double cosTheta) const {
    return fluence(l) + 3.0 * d() * fluenceSlope(l) * cosTheta;
  }
};

/// The mean of cos theta over a square image of `fovDeg` (box pixels:
/// uniform on the image plane), by a `cells` x `cells` midpoint rule: the
/// closed forms' radiance seen through the camera's pixels.
inline double meanImageCosine(double fovDeg, int cells) {
  const double a = std::tan(fovDeg * kPi / 360.0);
  double s = 0.0;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const double u = a * (2.0 * (i + 0.5) / cells - 1.0), v = a * (2.0 * (j + 0.5) / cells - 1.0);
      s += 1.0 / std::sqrt(1.0 + u * u + v * v);
    }
  }
  return s / (static_cast<double>(cells) * cells);
}

}  // namespace tofsim::test::diffusion
