#pragma once
// Free flights along one leg of a path, through the homogeneous medium that
// fills the scene (SpectralFlight, unchanged bytes) or through per-region
// media (capture::MediumRegions, issue 42's `media:`): the leg is then
// piecewise homogeneous, sigma_t(t) the region's inside it and 0 between
// regions. The same spectral MIS as SpectralFlight: a channel c picked
// uniformly, an optical depth tau = -ln(1 - u) drawn, the event where the
// channel's optical depth along the leg reaches tau; every channel weighted
// by the mixture's density p(t) = mean_c sigma_t,c(t) T_c(t), the pass by
// P(d) = mean_c T_c(d). A leg that crosses no scattering region is not
// sampled (no draws in a scene whose regions only absorb).
// One sampler for both renderers' paths through regions: the reference path
// tracer's legs (core/reference/src/MediumPaths.cpp) and IR's region VPLs
// (ir::lightRegionVpls: the light's rays, by sampleBeforeEnd, an event
// always before the leg's end; ir::traceBounce: later bounces' rays, by
// sample).

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "tofsim/ir/SpectralFlight.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/util/Random.h"

namespace tofsim::ir {

class LegFlight {
 public:
  /// The homogeneous medium's flights (every leg the same).
  explicit LegFlight(const SpectralFlight& homogeneous) : homogeneous_(&homogeneous) {}
  /// The regions' flights along origin + t dir (unit), t in [0, length_m].
  LegFlight(const capture::MediumRegions& regions, const glm::dvec3& origin, const glm::dvec3& dir,
            double length_m)
      : regions_(&regions) {
    regions.spans(origin, dir, length_m, spans_);
    depthBefore_.reserve(spans_.size());
    glm::dvec3 depth(0.0);
    for (const capture::RegionSpan& s : spans_) {
      depthBefore_.push_back(depth);
      depth += sigmaT(s) * (s.t1_m - s.t0_m);
      scatters_ = scatters_ || regions.medium(s.region).medium.scatters();
    }
  }

  bool scatters() const { return homogeneous_ ? homogeneous_->scatters() : scatters_; }

  /// Distance to the next medium event (SpectralFlight::kNone: none on the leg).
  double sample(Pcg32& rng) const {
    if (homogeneous_) return homogeneous_->sample(rng);
    if (!scatters_) return SpectralFlight::kNone;
    const auto channel = static_cast<int>(rng.nextUint() % 3u);
    const double tau = -std::log1p(-rng.nextDouble());
    for (std::size_t i = 0; i < spans_.size(); ++i) {
      const double s = sigmaT(spans_[i])[channel];
      const double before = depthBefore_[i][channel];
      const double inside = s * (spans_[i].t1_m - spans_[i].t0_m);
      if (s > 0.0 && tau < before + inside) return spans_[i].t0_m + (tau - before) / s;
    }
    return SpectralFlight::kNone;
  }

  /// Regions only: an event drawn before the leg's end (length_m), always in
  /// a region: the channel c among those with optical depth tau_c(end) > 0,
  /// tau drawn from exp(-tau) truncated to [0, tau_c(end)) (kNone, without
  /// a draw, where every channel's depth is 0 or no region on the leg
  /// scatters). Its density is pdfBeforeEnd.
  double sampleBeforeEnd(Pcg32& rng) const {
    if (!scatters_) return SpectralFlight::kNone;  // an event there would scatter nothing
    const glm::dvec3 total = depthTo(SpectralFlight::kNone);
    int channels[3], count = 0;
    for (int c = 0; c < 3; ++c) {
      if (total[c] > 0.0) channels[count++] = c;
    }
    if (count == 0) return SpectralFlight::kNone;
    const int channel = channels[rng.nextUint() % static_cast<uint32_t>(count)];
    const double tau = -std::log1p(-rng.nextDouble() * -std::expm1(-total[channel]));
    for (std::size_t i = 0; i < spans_.size(); ++i) {
      const double s = sigmaT(spans_[i])[channel];
      const double before = depthBefore_[i][channel];
      const double inside = s * (spans_[i].t1_m - spans_[i].t0_m);
      if (s > 0.0 && tau < before + inside) {
        return std::min(spans_[i].t0_m + (tau - before) / s, std::nextafter(spans_[i].t1_m, 0.0));
      }
    }
    return SpectralFlight::kNone;  // rounding past the last span: no event
  }
  /// sampleBeforeEnd's density at t, 1/m: mean over its channels of
  /// sigma_t,c(t) T_c(t) / (1 - T_c(end)).
  double pdfBeforeEnd(double t) const {
    const glm::dvec3 total = depthTo(SpectralFlight::kNone);
    const glm::dvec3 st = sigmaT(at(t)) * transmittance(t);
    double sum = 0.0;
    int count = 0;
    for (int c = 0; c < 3; ++c) {
      if (!(total[c] > 0.0)) continue;
      sum += st[c] / -std::expm1(-total[c]);
      ++count;
    }
    return count > 0 ? sum / count : 0.0;
  }
  /// sigma_t(t) T(t) per channel: the share of the light extinguished at t
  /// (a medium VPL's flux, before its density is divided out).
  glm::dvec3 extinguished(double t) const { return sigmaT(at(t)) * transmittance(t); }
  /// exp(-optical depth from 0 to t) per channel.
  glm::dvec3 transmittance(double t) const {
    if (homogeneous_) return homogeneous_->transmittance(t);
    return glm::exp(-depthTo(t));
  }
  /// The mixture density of an event at t, 1/m.
  double pdf(double t) const {
    if (homogeneous_) return homogeneous_->pdf(t);
    if (!scatters_) return 0.0;
    const glm::dvec3 st = sigmaT(at(t)) * transmittance(t);
    return (st.x + st.y + st.z) / 3.0;
  }
  /// T(t) sigma_s(t) per channel.
  glm::dvec3 scattered(double t) const {
    if (homogeneous_) return homogeneous_->scattered(t);
    const capture::RegionSpan* s = at(t);
    return s ? transmittance(t) * glm::dvec3(regions_->medium(s->region).medium.sigma_s_per_m)
             : glm::dvec3(0.0);
  }
  glm::dvec3 scatterWeight(double t) const {
    if (homogeneous_) return homogeneous_->scatterWeight(t);
    const double p = pdf(t);
    return p > 0.0 ? scattered(t) / p : glm::dvec3(0.0);
  }
  /// T(d) / P(d): flying past d to the surface.
  glm::dvec3 passWeight(double d) const {
    if (homogeneous_) return homogeneous_->passWeight(d);
    const glm::dvec3 tr = transmittance(d);
    if (!scatters_) return tr;
    const double p = (tr.x + tr.y + tr.z) / 3.0;
    return p > 0.0 ? tr / p : glm::dvec3(0.0);
  }
  /// The time's extra path from 0 to t (capture::RegionPassage::extraPath_m).
  double extraPath_m(double t) const {
    double extra = 0.0;
    for (const capture::RegionSpan& s : spans_) {
      if (s.t0_m >= t) break;
      extra += regions_->delayPerMetre(s.region) * (std::min(t, s.t1_m) - s.t0_m);
    }
    return extra;
  }
  /// The medium at t (a scattering event's phase function); nullptr: the
  /// homogeneous medium's.
  const capture::Medium* mediumAt(double t) const {
    const capture::RegionSpan* s = homogeneous_ ? nullptr : at(t);
    return s ? &regions_->medium(s->region).medium : nullptr;
  }

 private:
  glm::dvec3 sigmaT(const capture::RegionSpan* s) const {
    return s ? sigmaT(*s) : glm::dvec3(0.0);
  }
  glm::dvec3 sigmaT(const capture::RegionSpan& s) const {
    return glm::dvec3(regions_->medium(s.region).medium.sigmaT());
  }
  // The span holding t (nullptr: between regions).
  const capture::RegionSpan* at(double t) const {
    for (const capture::RegionSpan& s : spans_) {
      if (t >= s.t0_m && t < s.t1_m) return &s;
    }
    return nullptr;
  }
  glm::dvec3 depthTo(double t) const {
    glm::dvec3 depth(0.0);
    for (std::size_t i = 0; i < spans_.size() && spans_[i].t0_m < t; ++i) {
      depth = depthBefore_[i] + sigmaT(spans_[i]) * (std::min(t, spans_[i].t1_m) - spans_[i].t0_m);
    }
    return depth;
  }

  const SpectralFlight* homogeneous_ = nullptr;
  const capture::MediumRegions* regions_ = nullptr;
  std::vector<capture::RegionSpan> spans_;
  std::vector<glm::dvec3> depthBefore_;  ///< optical depth at each span's start
  bool scatters_ = false;
};

}  // namespace tofsim::ir
