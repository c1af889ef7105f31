#pragma once
// A camera ray's stretches inside per-region media (issue 42's `media:`), as
// the CPU backend's region passes integrate along them
// (CpuRegionDirect.cpp; core/physics/medium_single_scattering.md, "In
// regions"): each stretch is homogeneous (its region's sigma_s, sigma_t,
// phase function and index), what the ray crossed before it (optical depth,
// the time's extra path) is a constant, and inside it both grow linearly.
// Only the light leg's passage (the emitter -> scattering point leg through
// the regions) varies otherwise: it is asked of MediumRegions point by point.

#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "tofsim/capture/MediumRegions.h"

namespace tofsim::cpu {

/// Camera-ray parameter s in [t0_m, t1_m) inside region `region`.
struct RegionSegment {
  double t0_m = 0.0, t1_m = 0.0;
  int32_t region = 0;
  glm::dvec3 depthBefore{0.0};  ///< the camera leg's optical depth from the ray's origin to t0
  double extraBefore_m = 0.0;   ///< its extra path (RegionPassage::extraPath_m) to t0
};

/// The stretches of origin + s dir (unit dir), s in [0, length_m]
/// (infinity: the whole ray), inside regions, in order, into `out`.
inline void regionSegments(const capture::MediumRegions& regions, const glm::dvec3& origin,
                           const glm::dvec3& dir, double length_m,
                           std::vector<RegionSegment>& out) {
  out.clear();
  thread_local std::vector<capture::RegionSpan> spans;
  regions.spans(origin, dir, length_m, spans);
  glm::dvec3 depth(0.0);
  double extra = 0.0;
  for (const capture::RegionSpan& s : spans) {
    out.push_back({s.t0_m, s.t1_m, s.region, depth, extra});
    const double inside = s.t1_m - s.t0_m;
    depth += glm::dvec3(regions.medium(s.region).medium.sigmaT()) * inside;
    extra += regions.delayPerMetre(s.region) * inside;
  }
}

/// The geometric path (metres at the time axis' index: the optical path /
/// eta) of the light an emitter at `emitter` sends to the point at s of a
/// timed camera ray's segment, scattered there toward the camera: the light
/// leg with its passage through the regions, then s, the lens's path, and
/// the camera leg's extra path in the regions up to s. Nondecreasing in s
/// wherever the light leg's time varies smoothly (its end moves at most
/// eta_r / eta_axis of path per metre of s while the camera leg grows by
/// that much), so each bin's edge is one s, found by regula falsi (sAt)
/// between the previous edge and the segment's end: the bins' parts
/// partition the segment whatever the path does (a light leg grazing a
/// region's face may bend it), so no light is lost nor counted twice.
class RegionSegmentPath {
 public:
  RegionSegmentPath(const capture::MediumRegions& regions, const RegionSegment& segment,
                    const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& emitter,
                    double lensPath_m)
      : regions_(regions),
        segment_(segment),
        origin_(origin),
        dir_(dir),
        emitter_(emitter),
        lensPath_m_(lensPath_m),
        delay_(regions.delayPerMetre(segment.region)) {}

  double at(double s) const {
    const glm::dvec3 x = origin_ + dir_ * s;
    return glm::length(x - emitter_) + regions_.passage(x, emitter_).extraPath_m + s + lensPath_m_ +
           segment_.extraBefore_m + delay_ * (s - segment_.t0_m);
  }

  /// The s in [lo, hi] where the path is q, given pathLo = at(lo) <= q <=
  /// pathHi = at(hi): the Illinois variant of regula falsi (superlinear on
  /// the smooth path), to 1e-12 of the segment's scale.
  double sAt(double q, double lo, double pathLo, double hi, double pathHi) const {
    const double tolerance = 1e-12 * (1.0 + std::abs(hi) + std::abs(lo));
    int side = 0;
    for (int i = 0; i < 100 && hi - lo > tolerance; ++i) {
      const double flo = pathLo - q, fhi = pathHi - q;
      double s = fhi != flo ? lo - flo * (hi - lo) / (fhi - flo) : 0.5 * (lo + hi);
      if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
      const double path = at(s);
      if (path < q) {
        lo = s;
        pathLo = path;
        if (side == -1) pathHi = q + 0.5 * (pathHi - q);  // Illinois: halve the stale end
        side = -1;
      } else {
        hi = s;
        pathHi = path;
        if (side == 1) pathLo = q + 0.5 * (pathLo - q);
        side = 1;
      }
    }
    return 0.5 * (lo + hi);
  }

 private:
  const capture::MediumRegions& regions_;
  const RegionSegment& segment_;
  glm::dvec3 origin_, dir_, emitter_;
  double lensPath_m_;
  double delay_;
};

}  // namespace tofsim::cpu
