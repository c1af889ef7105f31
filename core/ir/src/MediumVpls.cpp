#include "tofsim/ir/MediumVpls.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "tofsim/ir/LegFlight.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/HemisphereSampling.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/ParallelFor.h"
#include "tofsim/util/Random.h"

namespace tofsim::ir {

namespace {

// Generator units of the light's medium VPLs, apart from the bounces'
// (BounceVpls.cpp's 0xB0, 0xB1) and any other user of the seed.
constexpr uint64_t kLightRayUnit = uint64_t{0xB2} << 56;

// Rays per task: a fixed split, so that each task writes its own slots.
constexpr std::size_t kRaysPerTask = 256;

// One ray of the light drawn from its emission profile, and the power it
// carries per unit of count (W): intensity x profile / pdf.
struct LightRay {
  glm::vec3 direction;
  glm::vec3 power_W;
};

LightRay sampleLightRay(const capture::Light& light, float u1, float u2) {
  const capture::Light::ProfileTerms p = light.profileTerms();
  if (p.kind == physics::LIGHT_LAMBERTIAN) {
    // pdf cos / pi against the profile's cos: pi x intensity.
    return {physics::cosineSampleHemisphere(p.axis, u1, u2),
            light.intensity_W_per_sr * static_cast<float>(M_PI)};
  }
  // Uniform over the cap cos >= cosOuter (the whole sphere for a point
  // light): pdf 1 / its solid angle.
  const float cosOuter = p.kind == physics::LIGHT_POINT ? -1.0f : p.cosOuter;
  const float cosTheta = 1.0f - u1 * (1.0f - cosOuter);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * static_cast<float>(M_PI) * u2;
  const glm::vec3 w = glm::normalize(
      physics::basisAround(p.axis) *
      glm::vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
  const float solidAngle = 2.0f * static_cast<float>(M_PI) * (1.0f - cosOuter);
  const float profile = physics::lightProfile(p.kind, p.axis, p.cosOuter, p.cosInner, w);
  return {w, light.intensity_W_per_sr * (profile * solidAngle)};
}

// `count` rays of the light, each with its own generator (seed, its index:
// the bytes do not depend on `threads`), in fixed runs: each ray drawn from
// the light's emission (its first two draws), dark ones skipped, traced to
// its first surface; `vplOf(rng, ray, hit_m)` (hit_m kNoHit when it leaves
// the scene) is its VPL or none. The VPLs in ray order.
template <class VplOf>
std::vector<Vpl> lightRayVpls(const rays::RayScene& scene, const capture::Light& light,
                              std::size_t count, uint64_t seed, int32_t threads,
                              const VplOf& vplOf) {
  std::vector<std::optional<Vpl>> slots(count);
  const std::size_t tasks = (count + kRaysPerTask - 1) / kRaysPerTask;
  parallelFor(tasks, resolveThreads(threads), [&](std::size_t task) {
    const std::size_t end = std::min(count, (task + 1) * kRaysPerTask);
    for (std::size_t j = task * kRaysPerTask; j < end; ++j) {
      Pcg32 rng = Pcg32::forUnit(seed, kLightRayUnit | static_cast<uint64_t>(j));
      const float u1 = rng.nextFloat();
      const float u2 = rng.nextFloat();
      const LightRay ray = sampleLightRay(light, u1, u2);
      if (!(ray.power_W.r + ray.power_W.g + ray.power_W.b > 0.0f)) continue;
      const auto hit = scene.intersect(light.position_world, ray.direction);
      slots[j] = vplOf(rng, ray, hit ? static_cast<double>(hit->distance_m) : kNoHit);
    }
  });
  std::vector<Vpl> vpls;
  vpls.reserve(count);
  for (const std::optional<Vpl>& v : slots) {
    if (v) vpls.push_back(*v);
  }
  return vpls;
}

}  // namespace

FreeFlight sampleFreeFlight(const capture::Medium& medium, double hit_m, bool truncated, double u) {
  const glm::dvec3 sigmaT(medium.sigmaT());
  const double mean = (sigmaT.x + sigmaT.y + sigmaT.z) / 3.0;
  FreeFlight f;
  if (!(mean > 0.0)) return f;  // nothing to stop at: the hit, unweighted
  // exp(-mean D): the probability of reaching the hit (0 with no hit).
  const double reach = std::isinf(hit_m) ? 0.0 : std::exp(-mean * hit_m);
  const double t = truncated ? -std::log1p(-u * (1.0 - reach)) / mean : -std::log1p(-u) / mean;
  if (!truncated && !(t < hit_m)) {
    const glm::dvec3 w = glm::exp(-(sigmaT - mean) * hit_m);  // exp(-sigma_t D) / exp(-mean D)
    f.weight = glm::vec3(w);
    return f;
  }
  const double pdf = mean * std::exp(-mean * t) / (truncated ? 1.0 - reach : 1.0);
  const glm::dvec3 extinguished = sigmaT * glm::exp(-sigmaT * t);
  f.inMedium = true;
  f.t_m = t;
  f.weight = glm::vec3(extinguished / pdf);
  return f;
}

std::vector<Vpl> lightMediumVpls(const rays::RayScene& scene, const capture::Light& light,
                                 const capture::Medium& medium, std::size_t count, uint64_t seed,
                                 double indexOfRefraction, int32_t threads,
                                 const physics::ResponseClassTable* classes) {
  if (count == 0 || !medium.scatters()) return {};
  const float perRay = 1.0f / static_cast<float>(count);
  const auto eta = static_cast<float>(indexOfRefraction);
  const bool delayed = classes != nullptr && classes->delayed();
  return lightRayVpls(scene, light, count, seed, threads,
                      [&](Pcg32& rng, const LightRay& ray, double hit_m) -> std::optional<Vpl> {
    const FreeFlight f = sampleFreeFlight(medium, hit_m, true, rng.nextDouble());
    if (!f.inMedium) return std::nullopt;
    const auto t = static_cast<float>(f.t_m);
    Vpl v = mediumVpl(light.position_world + ray.direction * t, eta * t,
                      ray.power_W * perRay * f.weight, -ray.direction, medium, 0.0f);
    if (delayed) v.flux.w = vplClassAfter(*classes, 0, v.vertex);
    return v;
  });
}

std::vector<Vpl> lightRegionVpls(const rays::RayScene& scene, const capture::Light& light,
                                 const capture::MediumRegions& regions, std::size_t count,
                                 uint64_t seed, double indexOfRefraction, int32_t threads,
                                 const physics::ResponseClassTable* classes) {
  if (count == 0 || !regions.scatters()) return {};
  const float perRay = 1.0f / static_cast<float>(count);
  const bool delayed = classes != nullptr && classes->delayed();
  return lightRayVpls(scene, light, count, seed, threads,
                      [&](Pcg32& rng, const LightRay& ray, double hit_m) -> std::optional<Vpl> {
    const LegFlight leg(regions, glm::dvec3(light.position_world), glm::dvec3(ray.direction), hit_m);
    const double t = leg.sampleBeforeEnd(rng);
    const capture::Medium* region = t < kNoHit ? leg.mediumAt(t) : nullptr;
    if (region == nullptr || !region->scatters()) return std::nullopt;
    const glm::vec3 weight(leg.extinguished(t) / leg.pdfBeforeEnd(t));
    const double path_m = indexOfRefraction * (t + leg.extraPath_m(t));
    Vpl v = mediumVpl(light.position_world + ray.direction * static_cast<float>(t),
                      static_cast<float>(path_m),
                      ray.power_W * perRay * weight, -ray.direction, *region, 0.0f);
    if (delayed) v.flux.w = vplClassAfter(*classes, 0, v.vertex);
    return v;
  });
}

}  // namespace tofsim::ir
