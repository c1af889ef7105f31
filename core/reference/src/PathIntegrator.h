#pragma once
// The per-pixel estimator of the reference renderer. Accumulates one pixel's
// direct and indirect histograms; knows nothing of threads or segments, nor
// of the imager's kind: its primary rays come from capture::PrimaryRays.

#include <cstdint>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/util/Random.h"
#include "tofsim/ir/LegFlight.h"
#include "tofsim/ir/SpectralFlight.h"
#include "tofsim/reference/Equiangular.h"
#include "VertexDelay.h"

namespace tofsim::reference {

using rays::SurfaceHit;
// Free flights by spectral MIS (tofsim/ir/LegFlight.h, shared with IR's
// region VPLs).
using ir::LegFlight;
using ir::SpectralFlight;

struct PixelOutput {
  float* direct = nullptr;    ///< T * 3 floats, zeroed by the caller
  float* indirect = nullptr;  ///< T * 3 floats, zeroed by the caller
  float depth_m = 0.0f;       ///< viewpoint-to-surface distance; 0 when no surface
  AxisLoss offAxis;           ///< radiance (summed over channels) off the time axis
};

class PathIntegrator {
 public:
  /// bounces >= 1; samplesPerPixel >= 1. A point set whose points have no
  /// extent (zero steps) is always rendered with the point filter: its
  /// pixels are points, there is no area to jitter over.
  PathIntegrator(const RayScene& scene, const capture::RenderJob& job, int32_t bounces,
                 int32_t samplesPerPixel, PixelFilter pixelFilter,
                 ContinuationSampling sampling = ContinuationSampling::BrdfMixture);

  /// Renders pixel (x, y). `scratch` is reused between calls of one thread.
  void renderPixel(int32_t x, int32_t y, PixelOutput& out, std::vector<double>& scratch) const;

 private:
  struct Radiance {
    glm::dvec3 value{0.0};
    double path_m = 0.0;  ///< geometric distance light -> surface, metres
    bool valid = false;
  };
  /// Radiance `hit` reflects towards `toViewer` (unit, on its normal side)
  /// straight from the light, tested with one shadow ray; path_m is the
  /// light -> hit distance. The BRDF is render.materials' (Lambertian: the
  /// same for every toViewer).
  Radiance lightReflectedAt(const SurfaceHit& hit, const glm::vec3& toViewer) const;
  /// The next direction of a path at `hit` seen from toViewer, and the factor
  /// f cos / pdf its throughput gains (0: the path ends).
  struct Continuation {
    glm::vec3 direction{0.0f};
    glm::dvec3 weight{0.0};
    /// The path ends here (only the mixture ends paths on a zero weight: the
    /// cosine paths keep the random stream of the renderer before it).
    bool ends = false;
  };
  /// Lambertian, or glTF with ContinuationSampling::Cosine: a cosine-sampled
  /// direction (two draws), weight albedo or pi f. glTF with BrdfMixture: the
  /// cosine + GGX VNDF mixture (three draws), weight f cos / mixture pdf.
  Continuation sampleContinuation(const SurfaceHit& hit, const glm::vec3& toViewer,
                                  Pcg32& rng) const;
  /// Point filter: one primary ray through the pixel centre, direct term exact.
  void renderPixelCentre(int32_t x, int32_t y, PixelOutput& out,
                         std::vector<double>& scratch) const;
  /// Box filter: every path starts at its own stratified sub-pixel point.
  void renderPixelArea(int32_t x, int32_t y, PixelOutput& out, std::vector<double>& scratch) const;
  // The pixel's sums over its samples (direct, indirect: `floats` each; the
  // light off the axis), divided by the sample count, into `out`.
  void storeAverages(const double* direct, const double* indirect, std::size_t floats,
                     const AxisLoss& outside, PixelOutput& out) const;
  /// Point filter at a primary hit whose material delays: the direct term
  /// too is averaged over the pixel's paths, each of which draws the hit's
  /// delay once for its direct light and its continuation.
  void renderDelayedCentre(const SurfaceHit& hit, const glm::vec3& toCamera, double toCamera_m,
                           int32_t x, int32_t y, PixelOutput& out,
                           std::vector<double>& scratch) const;
  /// Adds the direct light reflected at `hit` towards the camera (unit
  /// toCamera), seen through the path's state (its weight and delays, the
  /// hit's own included), to `histogram` (T x 3).
  void addDirect(const SurfaceHit& hit, const glm::vec3& toCamera, double toCamera_m,
                 const PathState& state, double* histogram, AxisLoss& outside) const;
  /// One path's bounces 2..n from the primary hit, seen from the unit
  /// direction toCamera, added to `histogram`. `state` holds the primary
  /// hit's delay; `delays` draws the later vertices'.
  void traceContinuation(const SurfaceHit& hit, const glm::vec3& toCamera, double toCamera_m,
                         PathState state, Pcg32& rng, Pcg32& delays, double* histogram,
                         AxisLoss& outside) const;
  /// Adds `value` at the arrival time of a geometric path length (metres,
  /// before the index of refraction) plus `delay_s`, or books it off the axis.
  void deposit(const glm::dvec3& value, double path_m, double delay_s, double* histogram,
               AxisLoss& outside) const;
  /// Time bin of a geometric path length (metres, before the index of
  /// refraction) plus the path's scattering delays (seconds), -1 when it
  /// falls off the axis. Same rule as TimeAxis::binOf.
  int32_t binOfPath(double path_m, double delay_s = 0.0) const;
  /// The base kernel of the material at `hit` (0: instant).
  int32_t responseAt(const SurfaceHit& hit) const {
    return materials_.at(static_cast<std::size_t>(hit.material)).response;
  }
  /// The generator of pixel `pixel`'s delays: a stream of its own, so that
  /// the directions a path draws do not depend on its delays.
  Pcg32 delayStream(uint64_t pixel) const;
  /// One pixel's paths' sums (direct, indirect: `floats` doubles each, in
  /// the caller's scratch, zeroed), the light off the axis, and the pixel's
  /// two generators (its paths' and its delays').
  struct PixelSums {
    std::size_t floats;
    double* direct;
    double* indirect;
    AxisLoss outside;
    Pcg32 rng;
    Pcg32 delays;
  };
  /// Every pixel's preamble (area, medium, delayed centre, point indirect):
  /// the depth image's value (the centre ray's first surface, as the
  /// G-buffer's), the zeroed sums in `scratch`, the generators.
  PixelSums beginPixel(int32_t x, int32_t y, PixelOutput& out, std::vector<double>& scratch) const;
  /// A path's state as it leaves the light: the light's own surface's delay
  /// (and re-emission) drawn once, for every vertex the path lights.
  PathState startPath(Pcg32& delays) const;

  // The medium that fills the scene (issue 42; MediumPaths.cpp). Without one
  // (!medium.present()) none of these runs: the bytes of before.
  /// Both filters: each of the pixel's paths starts through its own
  /// sub-pixel point (box) or the centre (point), and every term, the direct
  /// one included, is averaged over the paths (the first leg is sampled).
  void renderPixelInMedium(int32_t x, int32_t y, PixelOutput& out,
                           std::vector<double>& scratch) const;
  /// One path from `eye` along unit `direction`: up to bounces_ vertices,
  /// each a surface or a medium event (free-flight sampling), each lit by
  /// next-event estimation through the medium; vertex 1's light goes to
  /// the pixel's `direct`, the later ones' to its `indirect`.
  void traceMediumPath(const glm::vec3& eye, const glm::vec3& direction, PixelSums& pixel) const;
  /// Adds the light that medium point p scatters towards the unit direction
  /// toViewer straight from the light (phase function x I x profile / d^2 x
  /// transmittance, one shadow ray) x `weight` (the point's T sigma_s over
  /// its sampling density, MIS-weighted), seen through `state`, at the path
  /// length path_m (viewpoint -> p, as timed) + d.
  /// `medium`: p's phase function (nullptr: the medium filling the scene).
  void addMediumLight(const glm::vec3& p, const glm::vec3& toViewer, const PathState& state,
                      const glm::dvec3& weight, double path_m, double* histogram,
                      AxisLoss& outside, const capture::Medium* medium = nullptr) const;
  /// The flights along a leg from `origin` (unit dir, up to length_m).
  LegFlight legFlight(const glm::vec3& origin, const glm::vec3& dir, double length_m) const {
    return regions_.empty() ? LegFlight(flight_)
                            : LegFlight(regions_, glm::dvec3(origin), glm::dvec3(dir), length_m);
  }

  /// Length of the last leg (surface -> viewpoint, metres) that counts in
  /// the time: 0 with camera_unwarp or a point set that drops it.
  double lastLeg_m(double surfaceToViewpoint_m) const;
  /// Row-major index of pixel (x, y): its generator's unit.
  uint64_t pixelIndex(int32_t x, int32_t y) const {
    return static_cast<uint64_t>(y) * static_cast<uint64_t>(width_) + static_cast<uint64_t>(x);
  }

  const RayScene& scene_;
  const capture::RenderJob& job_;
  capture::PrimaryRays rays_;  ///< the imager's rays, a pinhole's frame computed once
  bool dropLastLeg_;
  int32_t width_;
  int32_t bounces_;
  int32_t samplesPerPixel_;
  PixelFilter pixelFilter_;
  bool gltf_;  ///< render.materials: gltf
  /// The scene's material vertices (ir::materialVertices; the glTF model's
  /// fields, read as the Lambertian albedo too).
  std::vector<physics::ScatterVertex> materials_;
  ContinuationSampling sampling_;
  /// The scene's delay kernels (ir::materialResponses), by base id.
  VertexDelays delays_;
  /// RenderSettings::media joined with the scene's regions (empty: none).
  capture::MediumRegions regions_;
  /// RenderSettings::medium present or media; the medium's flights (none
  /// with media); the equiangular points' phase model and g.
  bool inMedium_;
  SpectralFlight flight_;
  int32_t phase_;
  float g_;
  PhaseAngleTable angles_;  ///< the phase's scattering angles, for the equiangular points
  /// The base kernel of the light's own surface (ir::lightResponse; 0: none):
  /// every path's first delay.
  int32_t lightResponse_;
};

}  // namespace tofsim::reference
