#include "PathIntegrator.h"

#include <algorithm>
#include <cmath>

#include "tofsim/ir/HitVertex.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/physics/GltfBrdf.h"
#include "tofsim/physics/GltfSampling.h"
#include "tofsim/rays/Sampling.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::reference {

using rays::cosineSampleHemisphere;
using rays::stratifiedPixelOffset;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kChannels = 3;

// Points without extent are points: a box filter over them would only jitter
// every primary ray by zero (and spend draws doing it).
PixelFilter effectiveFilter(const capture::Imager& imager, PixelFilter requested) {
  return capture::pointPixels(imager) ? PixelFilter::Point : requested;
}
// The medium whose phase function the equiangular points are drawn for: the
// one filling the scene, else the first scattering region's (any is
// unbiased: each point's light is its own region's).
const capture::Medium& equiangularMedium(const capture::RenderSettings& s) {
  for (const capture::RegionMedium& r : s.media) {
    if (r.medium.scatters()) return r.medium;
  }
  return s.medium;
}
}  // namespace

PathIntegrator::PathIntegrator(const RayScene& scene, const capture::RenderJob& job,
                               int32_t bounces, int32_t samplesPerPixel, PixelFilter pixelFilter,
                               ContinuationSampling sampling)
    : scene_(scene),
      job_(job),
      rays_(job.imager),
      dropLastLeg_(job.settings.time.camera_unwarp || !capture::lastLegCounts(job.imager)),
      width_(capture::imageWidth(job.imager)),
      bounces_(bounces),
      samplesPerPixel_(samplesPerPixel),
      pixelFilter_(effectiveFilter(job.imager, pixelFilter)),
      gltf_(job.settings.materials == capture::MaterialModel::Gltf),
      materials_(ir::materialVertices(scene.scene(), physics::VERTEX_GLTF)),
      sampling_(sampling),
      delays_(ir::materialResponses(scene.scene()).kernels),
      regions_(job.settings.media, scene.scene(), job.settings.time.index_of_refraction),
      inMedium_(job.settings.medium.present() || !regions_.empty()),
      flight_(job.settings.medium),
      phase_(equiangularMedium(job.settings).phase),
      g_(equiangularMedium(job.settings).g),
      angles_(phase_, g_),
      lightResponse_(static_cast<int32_t>(
          ir::lightResponse(ir::materialResponses(scene.scene()), job.light))) {}

PathIntegrator::Radiance PathIntegrator::lightReflectedAt(const SurfaceHit& hit,
                                                          const glm::vec3& toViewer) const {
  // The GL direct gather's formula: f * I * profile * cos / r^2, f = albedo / pi
  // or the glTF BRDF (physics::gltfBrdf, the shaders' own).
  Radiance out;
  const capture::Light& light = job_.light;
  const glm::vec3 toLight = light.position_world - hit.position_world;
  const float d = glm::length(toLight);
  if (d <= 0.0f) return out;
  const glm::vec3 w = toLight / d;
  const float cosX = glm::dot(hit.normal_world, w);
  if (cosX <= 0.0f) return out;
  const float profile = light.angularProfile(-w);
  if (profile <= 0.0f) return out;
  if (scene_.occluded(scene_.offsetOrigin(hit, w), light.position_world)) return out;
  const physics::ScatterVertex v = ir::hitVertex(hit, materials_);
  const glm::vec3 albedo(v.color);
  if (gltf_) {
    const glm::vec3 f =
        physics::gltfBrdf(hit.normal_world, w, toViewer, albedo, v.color.w, v.roughness);
    const double scale = static_cast<double>(profile) * cosX / (static_cast<double>(d) * d);
    out.value = glm::dvec3(f) * glm::dvec3(light.intensity_W_per_sr) * scale;
  } else {
    const double scale = static_cast<double>(profile) * cosX / (static_cast<double>(d) * d) / kPi;
    out.value = glm::dvec3(albedo) * glm::dvec3(light.intensity_W_per_sr) * scale;
  }
  out.path_m = d;
  if (!regions_.empty()) {  // the light leg through the media's regions
    const capture::RegionPassage p =
        regions_.passage(glm::dvec3(light.position_world), glm::dvec3(hit.position_world));
    out.value *= p.transmittance();
    out.path_m += p.extraPath_m;
  }
  out.valid = true;
  return out;
}

double PathIntegrator::lastLeg_m(double surfaceToViewpoint_m) const {
  return dropLastLeg_ ? 0.0 : surfaceToViewpoint_m;
}

int32_t PathIntegrator::binOfPath(double path_m, double delay_s) const {
  const double optical_m = job_.settings.time.index_of_refraction * path_m;
  // + 0.0 for an undelayed path: the same arrival time, bit for bit.
  return job_.settings.time.binOf(optical_m / kSpeedOfLight_m_per_s + delay_s);
}

void PathIntegrator::deposit(const glm::dvec3& value, double path_m, double delay_s,
                             double* histogram, AxisLoss& outside) const {
  const int32_t b = binOfPath(path_m, delay_s);
  if (b < 0) {
    outside.add(b, value.r + value.g + value.b);
    return;
  }
  double* bin = histogram + static_cast<std::size_t>(b) * kChannels;
  for (int c = 0; c < kChannels; ++c) bin[c] += value[c];
}

Pcg32 PathIntegrator::delayStream(uint64_t pixel) const {
  constexpr uint64_t kDelayStreams = 0x6A09E667F3BCC909ull;  // any constant: not the paths' seeds
  return Pcg32::forUnit(job_.settings.seed ^ kDelayStreams, pixel);
}

void PathIntegrator::renderPixel(int32_t x, int32_t y, PixelOutput& out,
                                 std::vector<double>& scratch) const {
  if (inMedium_) {
    renderPixelInMedium(x, y, out, scratch);
  } else if (pixelFilter_ == PixelFilter::Point) {
    renderPixelCentre(x, y, out, scratch);
  } else {
    renderPixelArea(x, y, out, scratch);
  }
}

PathIntegrator::Continuation PathIntegrator::sampleContinuation(const SurfaceHit& hit,
                                                                const glm::vec3& toViewer,
                                                                Pcg32& rng) const {
  const float u1 = rng.nextFloat();
  const float u2 = rng.nextFloat();
  const physics::ScatterVertex v = ir::hitVertex(hit, materials_);
  const glm::vec3 albedo(v.color);
  Continuation out;
  if (gltf_ && sampling_ == ContinuationSampling::BrdfMixture) {
    // One-sample MIS over the cosine and GGX visible-normal lobes (balance
    // heuristic: f cos / the mixture's pdf). Point lights are delta lights, so
    // light sampling (next-event estimation) is the only strategy for the
    // direct light; the mixture is what combines strategies here.
    const float uLobe = rng.nextFloat();
    const physics::GltfBounce b = physics::sampleGltfBounce(
        hit.normal_world, toViewer, albedo, v.color.w, v.roughness, uLobe, u1, u2);
    out.direction = b.direction;
    out.weight = glm::dvec3(b.weight);
    out.ends = out.weight == glm::dvec3(0.0);
    return out;
  }
  out.direction = cosineSampleHemisphere(hit.normal_world, u1, u2);
  if (!gltf_) {
    out.weight = glm::dvec3(albedo);
  } else {
    // pdf = cos / pi: f cos / pdf = pi f, unbiased for any BRDF (noisy for glossy ones).
    out.weight = kPi * glm::dvec3(physics::gltfBrdf(hit.normal_world, out.direction, toViewer,
                                                    albedo, v.color.w, v.roughness));
  }
  return out;
}

void PathIntegrator::traceContinuation(const SurfaceHit& hit, const glm::vec3& toCamera,
                                       double toCamera_m, PathState state, Pcg32& rng,
                                       Pcg32& delays, double* histogram, AxisLoss& outside) const {
  // At each vertex the throughput gains f cos / pdf of the sampled direction
  // (albedo for a cosine-sampled Lambertian surface), and a vertex that
  // delays draws its delay (and re-emission) once, for the light it lights
  // directly and for the path's later vertices alike.
  SurfaceHit current = hit;
  glm::vec3 toViewer = toCamera;
  double fromCamera_m = toCamera_m;
  for (int32_t depth = 2; depth <= bounces_; ++depth) {
    const Continuation step = sampleContinuation(current, toViewer, rng);
    const glm::vec3 wi = step.direction;
    if (glm::dot(wi, current.geometric_world) <= 0.0f) break;  // below the true surface
    if (step.ends) break;  // mixture sample below the shading normal (or the float limit)
    const std::optional<SurfaceHit> next = scene_.intersect(scene_.offsetOrigin(current, wi), wi);
    if (!next) break;
    state.weight.scale(step.weight);
    delays_.atVertex(responseAt(*next), delays, state);
    toViewer = -wi;
    fromCamera_m += glm::length(next->position_world - current.position_world);
    const Radiance reflected = lightReflectedAt(*next, toViewer);
    if (reflected.valid) {
      deposit(state.seen(reflected.value), reflected.path_m + fromCamera_m, state.delay_s,
              histogram, outside);
    }
    current = *next;
  }
}

void PathIntegrator::renderPixelCentre(int32_t x, int32_t y, PixelOutput& out,
                                       std::vector<double>& scratch) const {
  // The last leg ends where the pixel's ray starts (an imager's rays may
  // each have their own origin).
  const capture::PrimaryRay ray = rays_.ray(x, y);
  const glm::vec3 eye = ray.origin;
  const std::optional<SurfaceHit> primary = scene_.intersect(eye, ray.direction);
  if (!primary) return;
  const SurfaceHit& hit = *primary;
  const double cameraLeg_m = glm::length(hit.position_world - eye);
  out.depth_m = static_cast<float>(cameraLeg_m);
  // Unwarped time (or a point set timed at its points) is the time at the
  // first surface: drop the surface -> viewpoint leg.
  const double toCamera_m = lastLeg_m(cameraLeg_m);
  const glm::vec3 toCamera = glm::normalize(eye - hit.position_world);
  if (delays_.delays(responseAt(hit)) || delays_.delays(lightResponse_)) {
    renderDelayedCentre(hit, toCamera, toCamera_m, x, y, out, scratch);
    return;
  }

  // Bounce 1: exact, no sampling.
  const Radiance direct = lightReflectedAt(hit, toCamera);
  if (direct.valid) {
    const int32_t b = binOfPath(direct.path_m + toCamera_m);
    if (b < 0) {
      out.offAxis.add(b, direct.value.r + direct.value.g + direct.value.b);
    } else {
      float* bin = out.direct + static_cast<std::size_t>(b) * kChannels;
      for (int c = 0; c < kChannels; ++c) bin[c] = static_cast<float>(direct.value[c]);
    }
  }
  if (bounces_ < 2) return;

  // Bounces 2..n: fixed-depth cosine-sampled paths with next-event estimation.
  PixelSums p = beginPixel(x, y, out, scratch);
  for (int32_t s = 0; s < samplesPerPixel_; ++s) {
    traceContinuation(hit, toCamera, toCamera_m, {}, p.rng, p.delays, p.indirect, p.outside);
  }
  // The direct term is exact, already in out.direct: only the paths' average.
  const double norm = 1.0 / samplesPerPixel_;
  for (std::size_t i = 0; i < p.floats; ++i) {
    out.indirect[i] = static_cast<float>(p.indirect[i] * norm);
  }
  out.offAxis.before += p.outside.before * norm;
  out.offAxis.after += p.outside.after * norm;
}

void PathIntegrator::renderDelayedCentre(const SurfaceHit& hit, const glm::vec3& toCamera,
                                         double toCamera_m, int32_t x, int32_t y,
                                         PixelOutput& out, std::vector<double>& scratch) const {
  PixelSums p = beginPixel(x, y, out, scratch);
  const int32_t response = responseAt(hit);
  const Radiance light = lightReflectedAt(hit, toCamera);  // the same for every path
  for (int32_t s = 0; s < samplesPerPixel_; ++s) {
    PathState state = startPath(p.delays);
    delays_.atVertex(response, p.delays, state);
    if (light.valid) {
      deposit(state.seen(light.value), light.path_m + toCamera_m, state.delay_s, p.direct,
              p.outside);
    }
    if (bounces_ >= 2) {
      traceContinuation(hit, toCamera, toCamera_m, state, p.rng, p.delays, p.indirect,
                        p.outside);
    }
  }
  storeAverages(p.direct, p.indirect, p.floats, p.outside, out);
}

PathIntegrator::PixelSums PathIntegrator::beginPixel(int32_t x, int32_t y, PixelOutput& out,
                                                     std::vector<double>& scratch) const {
  const capture::PrimaryRay centre = rays_.ray(x, y);
  if (const auto hit = scene_.intersect(centre.origin, centre.direction)) {
    out.depth_m = static_cast<float>(glm::length(hit->position_world - centre.origin));
  }
  const std::size_t floats = static_cast<std::size_t>(job_.settings.time.bins) * kChannels;
  scratch.assign(2 * floats, 0.0);
  const uint64_t pixel = pixelIndex(x, y);
  return PixelSums{floats, scratch.data(), scratch.data() + floats, AxisLoss{},
                   Pcg32::forUnit(job_.settings.seed, pixel), delayStream(pixel)};
}

PathState PathIntegrator::startPath(Pcg32& delays) const {
  PathState state;
  delays_.atLight(lightResponse_, delays, state);
  return state;
}

void PathIntegrator::storeAverages(const double* direct, const double* indirect,
                                   std::size_t floats, const AxisLoss& outside,
                                   PixelOutput& out) const {
  const double norm = 1.0 / samplesPerPixel_;
  for (std::size_t i = 0; i < floats; ++i) {
    out.direct[i] = static_cast<float>(direct[i] * norm);
    out.indirect[i] = static_cast<float>(indirect[i] * norm);
  }
  out.offAxis.before += outside.before * norm;
  out.offAxis.after += outside.after * norm;
}

void PathIntegrator::addDirect(const SurfaceHit& hit, const glm::vec3& toCamera, double toCamera_m,
                               const PathState& state, double* histogram,
                               AxisLoss& outside) const {
  const Radiance direct = lightReflectedAt(hit, toCamera);
  if (!direct.valid) return;
  deposit(state.seen(direct.value), direct.path_m + toCamera_m, state.delay_s, histogram, outside);
}

void PathIntegrator::renderPixelArea(int32_t x, int32_t y, PixelOutput& out,
                                     std::vector<double>& scratch) const {
  PixelSums p = beginPixel(x, y, out, scratch);
  const glm::vec3 eye = rays_.ray(x, y).origin;  // every ray of the pixel starts there
  for (int32_t s = 0; s < samplesPerPixel_; ++s) {
    const glm::vec2 offset = stratifiedPixelOffset(s, samplesPerPixel_, p.rng);
    const std::optional<SurfaceHit> hit =
        scene_.intersect(eye, rays_.ray(x, y, offset).direction);
    if (!hit) continue;  // a silhouette pixel: this part of it sees nothing
    const double toCamera_m = lastLeg_m(glm::length(hit->position_world - eye));
    const glm::vec3 toCamera = glm::normalize(eye - hit->position_world);
    PathState state = startPath(p.delays);
    delays_.atVertex(responseAt(*hit), p.delays, state);
    addDirect(*hit, toCamera, toCamera_m, state, p.direct, p.outside);
    if (bounces_ >= 2) {
      traceContinuation(*hit, toCamera, toCamera_m, state, p.rng, p.delays, p.indirect,
                        p.outside);
    }
  }
  storeAverages(p.direct, p.indirect, p.floats, p.outside, out);
}

}  // namespace tofsim::reference
