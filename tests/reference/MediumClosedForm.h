#pragma once
// Closed forms of a homogeneous medium for the reference's tests (issue 42),
// with the second moments of the reference's estimator, so that tolerances
// follow from the sample count: a camera with a point light at its pinhole
// (the lidar equation's geometry), render.indirect bounces 1, pixel centres.
// A path draws a free flight t from the spectral-MIS mixture
// p(t) = mean_c sigma_t,c exp(-sigma_t,c t) (tofsim/ir/SpectralFlight.h): if it scatters at
// t its estimate in channel c is T_c(t) sigma_s,c / p(t) x p(pi) I_c T_c(t) / t^2
// (deposited at round trip 2 t); if it reaches a surface at r, whose vacuum
// return is v_c, T_c(r) / P(r) x v_c T_c(r), P(r) = mean_c T_c(r). A light
// off the pixel's ray adds an equiangular point per path (balance heuristic
// with the free flight: each strategy's estimate f / (p_flight + p_equiangular),
// the density tofsim/reference/Equiangular.h's).

#include <cmath>

#include <glm/glm.hpp>

#include "tofsim/capture/Medium.h"
#include "tofsim/volume/PhysicalConstants.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::test {

/// Mean and second moment of one path's estimate in one bin and channel.
struct Moments {
  double mean = 0.0;
  double second = 0.0;
  void operator+=(const Moments& o) {
    mean += o.mean;
    second += o.second;
  }
  /// Standard error of the mean of n independent paths.
  double standardError(double n) const { return std::sqrt(std::max(0.0, second - mean * mean) / n); }
};

/// A time axis over geometric path lengths: bin b holds the paths of
/// geometric length [l0 + b width, l0 + (b + 1) width) (metres) in a medium
/// of index eta (the reference times eta x the geometric length).
inline TimeAxis pathAxis(double eta, double l0_m, double width_m, int32_t bins) {
  TimeAxis axis{eta * l0_m / kSpeedOfLight_m_per_s, eta * width_m / kSpeedOfLight_m_per_s, bins};
  axis.index_of_refraction = eta;
  return axis;
}

inline double mixturePdf(const capture::Medium& m, double t) {
  const glm::dvec3 st(m.sigmaT());
  return (st.x * std::exp(-st.x * t) + st.y * std::exp(-st.y * t) + st.z * std::exp(-st.z * t)) / 3.0;
}

/// The single-scattered (lidar) return of channel c from one-way distances
/// [s0, s1]: sigma_s p(pi) I int exp(-2 sigma_t s) / s^2 ds (Simpson), and
/// the estimator's second moment.
inline Moments lidarReturn(const capture::Medium& m, int c, double phaseBack, double intensity,
                           double s0, double s1) {
  Moments out;
  if (!(s1 > s0)) return out;
  constexpr int kSteps = 2000;  // even
  const double h = (s1 - s0) / kSteps;
  const double sigmaT = m.sigmaT()[c], sigmaS = m.sigma_s_per_m[c];
  for (int i = 0; i <= kSteps; ++i) {
    const double s = s0 + i * h;
    const double w = (i == 0 || i == kSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double f = sigmaS * phaseBack * intensity * std::exp(-2.0 * sigmaT * s) / (s * s);
    out.mean += w * f;
    out.second += w * f * f / mixturePdf(m, s);
  }
  out.mean *= h / 3.0;
  out.second *= h / 3.0;
  return out;
}

/// Mean and second-moment matrix of one path's estimates in one bin, the
/// three channels together: a path's one free flight serves every channel
/// (spectral MIS), so its channels' estimates are one draw's, strongly
/// correlated; their covariance (second - mean mean^T) is not diagonal.
struct ChannelMoments {
  glm::dvec3 mean{0.0};
  glm::dmat3 second{0.0};
  /// The covariance of the mean of n independent paths.
  glm::dmat3 covariance(double n) const {
    return (second - glm::outerProduct(mean, mean)) / n;
  }
  /// d^T covariance^-1 d for a difference d of the mean of n paths.
  double mahalanobis(const glm::dvec3& d, double n) const {
    return glm::dot(d, glm::inverse(covariance(n)) * d);
  }
  /// The mean v of n paths against this: a chi-square of 3 degrees of freedom.
  double chiSquare(const glm::dvec3& v, double n) const { return mahalanobis(v - mean, n); }
};

/// The single-scattered (lidar) return of the three channels from one-way
/// distances [s0, s1], as lidarReturn, with the estimator's second-moment
/// matrix int f f^T / p.
inline ChannelMoments lidarReturnChannels(const capture::Medium& m, double phaseBack,
                                          const glm::dvec3& intensity, double s0, double s1) {
  ChannelMoments out;
  if (!(s1 > s0)) return out;
  constexpr int kSteps = 2000;  // even
  const double h = (s1 - s0) / kSteps;
  const glm::dvec3 sigmaT(m.sigmaT()), sigmaS(m.sigma_s_per_m);
  for (int i = 0; i <= kSteps; ++i) {
    const double s = s0 + i * h;
    const double w = (i == 0 || i == kSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const glm::dvec3 f = sigmaS * phaseBack * intensity * glm::exp(-2.0 * sigmaT * s) / (s * s);
    out.mean += w * f;
    out.second += glm::outerProduct(f, f) * (w / mixturePdf(m, s));
  }
  out.mean *= h / 3.0;
  out.second *= h / 3.0;
  return out;
}

/// A surface at r whose return in vacuum is `vacuum` (channel c): the
/// medium's is vacuum x T(r)^2, reached with probability P(r).
inline Moments surfaceReturn(const capture::Medium& m, int c, double vacuum, double r) {
  const glm::dvec3 st(m.sigmaT());
  const double p = (std::exp(-st.x * r) + std::exp(-st.y * r) + std::exp(-st.z * r)) / 3.0;
  const double t2 = std::exp(-2.0 * st[c] * r);
  return {vacuum * t2, vacuum * vacuum * t2 * t2 / p};
}

}  // namespace tofsim::test
