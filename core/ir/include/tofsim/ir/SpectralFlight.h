#pragma once
// Free-flight distance sampling in the homogeneous medium that fills the
// scene (capture::Medium, per-channel sigma_t), for the reference path tracer
// (its legs through per-region media: LegFlight.h, which IR's region VPLs
// share). IR's medium VPLs in that medium draw theirs by the mean sigma_t
// instead (ir::sampleFreeFlight, MediumVpls.h): the bytes of its fog renders.
//
// Spectral MIS (one-sample, balance heuristic over the three channels; as in
// pbrt-v3's VolPathIntegrator and Miller, Georgiev and Jarosz 2019): a
// channel c is picked uniformly and a distance drawn from sigma_t,c
// exp(-sigma_t,c t); every channel is then weighted by the MIXTURE's density,
// p(t) = mean_c sigma_t,c exp(-sigma_t,c t), and the probability of flying
// past a surface at d by P(d) = mean_c exp(-sigma_t,c d). The mixture is
// positive wherever any channel's integrand is, so the estimate is unbiased
// for each channel's sigma_t (a channel with sigma_t = 0 flies straight to
// the surface), and no channel's weight blows up where another channel's
// density is small.
//
// A medium that only absorbs (sigma_s = 0 in every channel) cannot scatter:
// flights are not sampled at all (no draws), and every leg is attenuated by
// its transmittance exactly.

#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "tofsim/capture/Medium.h"
#include "tofsim/util/Random.h"

namespace tofsim::ir {

class SpectralFlight {
 public:
  explicit SpectralFlight(const capture::Medium& medium)
      : sigmaT_(medium.sigmaT()),
        sigmaS_(medium.sigma_s_per_m),
        scatters_(glm::any(glm::greaterThan(medium.sigma_s_per_m, glm::vec3(0.0f)))) {}

  /// Whether a path can scatter in the medium (some channel's sigma_s > 0).
  bool scatters() const { return scatters_; }

  /// Distance to the next medium event along a ray, metres (infinity: none;
  /// always infinity in a medium that does not scatter, without a draw).
  double sample(Pcg32& rng) const {
    if (!scatters_) return kNone;
    const uint32_t channel = rng.nextUint() % 3u;  // the bias of % 3 on 2^32 is 1e-10
    const double u = rng.nextDouble();               // [0, 1): 1 - u in (0, 1]
    const double s = sigmaT_[static_cast<int>(channel)];
    return s > 0.0 ? -std::log1p(-u) / s : kNone;
  }

  /// exp(-sigma_t d) per channel.
  glm::dvec3 transmittance(double d) const { return glm::exp(-sigmaT_ * d); }

  /// The density of a medium event at t (before any surface), 1/m: the
  /// mixture p(t) = mean_c sigma_t,c exp(-sigma_t,c t); 0 without scattering.
  double pdf(double t) const {
    if (!scatters_) return 0.0;
    const glm::dvec3 tr = transmittance(t);
    return (sigmaT_.x * tr.x + sigmaT_.y * tr.y + sigmaT_.z * tr.z) / 3.0;
  }

  /// T(t) sigma_s per channel: what scattering at t contributes before its
  /// sampling density is divided out.
  glm::dvec3 scattered(double t) const { return transmittance(t) * sigmaS_; }

  /// The throughput a path gains by scattering at t: T(t) sigma_s / p(t).
  glm::dvec3 scatterWeight(double t) const {
    const double p = pdf(t);
    return p > 0.0 ? scattered(t) / p : glm::dvec3(0.0);
  }

  /// The throughput a path gains by flying past distance d (to a surface):
  /// T(d) / P(d); T(d) itself when flights are not sampled.
  glm::dvec3 passWeight(double d) const {
    const glm::dvec3 tr = transmittance(d);
    if (!scatters_) return tr;
    const double p = (tr.x + tr.y + tr.z) / 3.0;
    return p > 0.0 ? tr / p : glm::dvec3(0.0);
  }

  static constexpr double kNone = std::numeric_limits<double>::infinity();

 private:
  glm::dvec3 sigmaT_;
  glm::dvec3 sigmaS_;
  bool scatters_;
};

}  // namespace tofsim::ir
