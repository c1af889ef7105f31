// The reference path tracer in the homogeneous medium that fills the scene
// (issue 42; core/reference/README.md, "In a medium"). A path's vertices are
// surfaces or medium events: along each leg a free flight is drawn
// (SpectralFlight, LegFlight: spectral MIS over the channels' sigma_t); if it ends before
// the next surface the path scatters there (throughput T sigma_s / p, a new
// direction drawn from the phase function, whose weight phase / pdf is 1),
// else it reaches the surface (throughput T / P) and continues as in vacuum.
// Every vertex is lit by next-event estimation with the light's transmittance
// on the shadow leg; the light the medium scatters along a leg is estimated
// by two strategies, the free flight's event and an equiangular point
// weighted by the phase function (tofsim/reference/Equiangular.h), combined
// by the balance heuristic; a medium event counts as a bounce (bounces_ vertices per
// path, vertex 1's light is `direct`). Times are eta x geometric length.

#include <cmath>

#include "PathIntegrator.h"
#include "tofsim/reference/Equiangular.h"
#include "tofsim/ir/HitVertex.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/rays/Sampling.h"

namespace tofsim::reference {

void PathIntegrator::renderPixelInMedium(int32_t x, int32_t y, PixelOutput& out,
                                         std::vector<double>& scratch) const {
  PixelSums p = beginPixel(x, y, out, scratch);
  const capture::PrimaryRay centre = rays_.ray(x, y);
  for (int32_t s = 0; s < samplesPerPixel_; ++s) {
    const glm::vec3 direction =
        pixelFilter_ == PixelFilter::Box
            ? rays_.ray(x, y, rays::stratifiedPixelOffset(s, samplesPerPixel_, p.rng)).direction
            : centre.direction;
    traceMediumPath(centre.origin, direction, p);
  }
  storeAverages(p.direct, p.indirect, p.floats, p.outside, out);
}

void PathIntegrator::traceMediumPath(const glm::vec3& eye, const glm::vec3& direction,
                                     PixelSums& pixel) const {
  Pcg32& rng = pixel.rng;
  AxisLoss& outside = pixel.outside;
  PathState state = startPath(pixel.delays);
  glm::vec3 position = eye;  // the current vertex
  glm::vec3 dir = direction;
  std::optional<SurfaceHit> surface;  // the current vertex when it is a surface
  double path_m = 0.0;                // viewpoint -> current vertex, as timed
  for (int32_t vertex = 1; vertex <= bounces_; ++vertex) {
    const glm::vec3 origin = surface ? scene_.offsetOrigin(*surface, dir) : position;
    const std::optional<SurfaceHit> next = scene_.intersect(origin, dir);
    // In float, as the vacuum paths measure their legs (the same bins).
    const double toSurface_m =
        next ? glm::length(next->position_world - position) : SpectralFlight::kNone;
    const LegFlight leg = legFlight(position, dir, toSurface_m);
    const double flight_m = leg.sample(rng);
    double* histogram = vertex == 1 ? pixel.direct : pixel.indirect;
    // The light the medium scatters towards the path along this leg, by two
    // strategies (balance heuristic): the free flight's event below, and an
    // equiangular point towards the light weighted by the phase function,
    // which cancels the 1 / d^2 of points near it and the phase's peak.
    // Only the free flight continues the path.
    Equiangular towardsLight(glm::dvec3(position), glm::dvec3(dir), toSurface_m,
                             glm::dvec3(job_.light.position_world), angles_);
    if (leg.scatters() && towardsLight.usable()) {
      const double t = towardsLight.sample(rng.nextDouble());
      if (t < toSurface_m) {
        const double pdf = towardsLight.pdf(t) + leg.pdf(t);
        const glm::vec3 p(glm::dvec3(position) + glm::dvec3(dir) * t);
        const double timed = t + leg.extraPath_m(t);
        addMediumLight(p, -dir, state, leg.scattered(t) / pdf,
                       path_m + (vertex == 1 ? lastLeg_m(timed) : timed), histogram, outside,
                       leg.mediumAt(t));
      }
    }
    if (flight_m < toSurface_m) {
      // A medium event: the light it scatters towards the path, then on.
      const double pdf = leg.pdf(flight_m);
      const double mis = pdf / (pdf + towardsLight.pdf(flight_m));
      const capture::Medium* here = leg.mediumAt(flight_m);
      position = glm::vec3(glm::dvec3(position) + glm::dvec3(dir) * flight_m);
      const double timed = flight_m + leg.extraPath_m(flight_m);
      path_m += vertex == 1 ? lastLeg_m(timed) : timed;
      addMediumLight(position, -dir, state, leg.scatterWeight(flight_m) * mis, path_m,
                     histogram, outside, here);
      state.weight.scale(leg.scatterWeight(flight_m));
      surface.reset();
      const float u1 = rng.nextFloat();
      const float u2 = rng.nextFloat();
      dir = glm::normalize(physics::samplePhaseDirection(here ? here->phase : phase_,
                                                         here ? here->g : g_, dir, u1, u2));
      continue;
    }
    if (!next) break;  // the path leaves the scene
    state.weight.scale(leg.passWeight(toSurface_m));
    delays_.atVertex(responseAt(*next), pixel.delays, state);
    const double timed = toSurface_m + leg.extraPath_m(toSurface_m);
    path_m += vertex == 1 ? lastLeg_m(timed) : timed;
    const glm::vec3 toViewer = -dir;
    const Radiance reflected = lightReflectedAt(*next, toViewer);
    if (reflected.valid) {
      deposit(state.seen(reflected.value * flight_.transmittance(reflected.path_m)),
              reflected.path_m + path_m, state.delay_s, histogram, outside);
    }
    if (vertex == bounces_) break;
    const Continuation step = sampleContinuation(*next, toViewer, rng);
    if (glm::dot(step.direction, next->geometric_world) <= 0.0f) break;  // below the surface
    if (step.ends) break;
    // A black surface (albedo 0): nothing the path meets later reaches the
    // camera. Ending it saves the rest of its vertices (the boundary of a
    // semi-infinite medium: ReferenceSemiInfiniteTest).
    if (step.weight == glm::dvec3(0.0)) break;
    state.weight.scale(step.weight);
    dir = step.direction;
    position = next->position_world;
    surface = next;
  }
}

void PathIntegrator::addMediumLight(const glm::vec3& p, const glm::vec3& toViewer,
                                    const PathState& state, const glm::dvec3& weight,
                                    double path_m, double* histogram, AxisLoss& outside,
                                    const capture::Medium* medium) const {
  const capture::Light& light = job_.light;
  const glm::dvec3 toLight = glm::dvec3(light.position_world) - glm::dvec3(p);
  const double d = glm::length(toLight);
  if (d <= 0.0) return;
  const glm::vec3 w(toLight / d);
  const float profile = light.angularProfile(-w);
  if (profile <= 0.0f) return;
  if (scene_.occluded(p, light.position_world)) return;
  // The light travels along -w and leaves towards the viewer.
  const double phase = physics::phaseFunction(medium ? medium->phase : phase_,
                                              medium ? medium->g : g_, glm::dot(-w, toViewer));
  glm::dvec3 value = glm::dvec3(light.intensity_W_per_sr) *
                     (phase * static_cast<double>(profile) / (d * d)) * flight_.transmittance(d) *
                     weight;
  double extra_m = 0.0;
  if (!regions_.empty()) {  // the light leg through the media's regions
    const capture::RegionPassage leg =
        regions_.passage(glm::dvec3(p), glm::dvec3(light.position_world));
    value *= leg.transmittance();
    extra_m = leg.extraPath_m;
  }
  deposit(state.seen(value), d + extra_m + path_m, state.delay_s, histogram, outside);
}

}  // namespace tofsim::reference
