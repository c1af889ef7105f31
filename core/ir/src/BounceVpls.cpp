#include "tofsim/ir/BounceVpls.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <thread>

#include "tofsim/ir/HitVertex.h"
#include "tofsim/ir/LegFlight.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/ir/MediumVpls.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ScatterSampling.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/rays/Sampling.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/ParallelFor.h"
#include "tofsim/util/Random.h"

namespace tofsim::ir {

namespace {

// Generator units of the bounce tracing, apart from any other user of the
// seed: the tag in the top byte, the bounce, then the child's index.
constexpr uint64_t kChildUnit = uint64_t{0xB0} << 56;
constexpr uint64_t kOffsetUnit = uint64_t{0xB1} << 56;

uint64_t unitOf(uint64_t tag, int32_t bounce, std::size_t index) {
  return tag | (static_cast<uint64_t>(bounce) << 32) | static_cast<uint64_t>(index);
}

double powerOf(const Vpl& v) { return static_cast<double>(v.flux.r) + v.flux.g + v.flux.b; }

// The flux of a child at vertex `child` that receives `share` of a parent of
// vertex `parent` through a continuation of `weight`. Where both fluxes are
// in the same units (both Lambertian: W/sr; neither: W) physics::bounceVplFlux,
// the floats of before; across them (a medium VPL's W and a Lambertian
// surface's W/sr, in a scattering medium) through the power the ray carries.
glm::vec3 childFlux(const physics::ScatterVertex& parent, const physics::ScatterVertex& child,
                    const glm::vec3& share, const glm::vec3& weight) {
  const bool cosineParent = physics::vplFluxHoldsScatter(parent);
  const bool cosineChild = physics::vplFluxHoldsScatter(child);
  if (cosineParent == cosineChild) return physics::bounceVplFlux(child, share, weight);
  const float pi = static_cast<float>(M_PI);
  // A Lambertian parent's share is albedo Phi / pi (W/sr), its cosine
  // sampling's weight 1: the ray carries pi times it.
  const glm::vec3 power = cosineParent ? share * pi : share * weight;
  return cosineChild ? glm::vec3(child.color) * power / pi : power;
}

// The direction a parent's light continues in and its weight f cos / pdf:
// a medium VPL's drawn from its phase function about the direction its light
// travelled (-incoming; weight: the albedo), a surface VPL's from its BRDF
// (physics::sampleVplContinuation).
physics::GltfBounce continuationOf(const Vpl& parent, float brdfClamp, Pcg32& rng) {
  if (isMediumVpl(parent)) {
    const physics::ScatterVertex& v = parent.vertex;
    const float u1 = rng.nextFloat();
    const float u2 = rng.nextFloat();
    return {physics::samplePhaseDirection(static_cast<int>(v.color.w), v.roughness,
                                          -glm::vec3(parent.incoming), u1, u2),
            glm::vec3(v.color)};
  }
  return physics::sampleVplContinuation(parent.vertex, glm::vec3(parent.normal),
                                        glm::vec3(parent.incoming), brdfClamp, rng);
}

// Child `index`'s light path continued from `parent`, whose power share is
// `share` (rgb: the parent's flux scaled to total power / count; W/sr, or W
// for glossy VPLs).
std::optional<Vpl> shootChild(const rays::RayScene& scene, const Vpl& parent,
                              const glm::vec3& share, int32_t bounce, uint64_t seed,
                              std::size_t index, float eta, const BounceTracing& tracing,
                              const BounceMaterials& materials,
                              const std::vector<physics::ScatterVertex>& vertices) {
  Pcg32 rng = Pcg32::forUnit(seed, unitOf(kChildUnit, bounce, index));
  const glm::vec3 p(parent.positionPath);
  const glm::vec3 n(parent.normal);  // 0 at a medium VPL: the ray starts at p
  const physics::GltfBounce continuation = continuationOf(parent, materials.brdfClamp, rng);
  const glm::vec3 w = continuation.direction;
  if (!isMediumVpl(parent) && !(glm::dot(w, n) > 0.0f)) return std::nullopt;
  const auto hit = scene.intersect(p + n * scene.epsilon_m(), w);
  // In a scattering medium the ray may end in it first (free flight): a
  // medium child standing for the power extinguished there, or the hit's
  // child weighted by its transmittance over the chance of getting there.
  std::optional<FreeFlight> flight;
  if (tracing.medium.scatters()) {
    flight = sampleFreeFlight(tracing.medium,
                              hit ? static_cast<double>(glm::length(hit->position_world - p)) : kNoHit,
                              false, rng.nextDouble());
  }
  // Per-region media: the leg's free flight through them (LegFlight's
  // spectral MIS, the reference's; no draw where the leg crosses no
  // scattering region, where it is the transmittance exactly).
  std::optional<LegFlight> regionLeg;
  double regionEvent_m = SpectralFlight::kNone;
  if (tracing.regions != nullptr && !tracing.regions->empty()) {
    regionLeg.emplace(*tracing.regions, glm::dvec3(p), glm::dvec3(w),
                      hit ? static_cast<double>(glm::length(hit->position_world - p)) : kNoHit);
    regionEvent_m = regionLeg->sample(rng);
  }
  std::optional<Vpl> child;
  physics::ScatterVertex vertex;
  // (The event's region: none where rounding put it on the region's far face.)
  const capture::Medium* eventRegion =
      regionEvent_m < SpectralFlight::kNone ? regionLeg->mediumAt(regionEvent_m) : nullptr;
  if (eventRegion != nullptr) {
    // A medium child in the region where the ray scatters: the power
    // extinguished there over the event's density, the region's phase.
    const double t = regionEvent_m;
    const capture::Medium& region = *eventRegion;
    vertex = physics::mediumVertex(region.albedo(), region.phase, region.g);
    const glm::vec3 flux = childFlux(parent.vertex, vertex, share, continuation.weight) *
                           glm::vec3(regionLeg->extinguished(t) / regionLeg->pdf(t));
    const double path_m = parent.positionPath.w + eta * (t + regionLeg->extraPath_m(t));
    if (flux.r + flux.g + flux.b > 0.0f) {
      child = mediumVpl(p + w * static_cast<float>(t), static_cast<float>(path_m), flux, -w, region,
                        0.0f);
    }
  } else if (flight && flight->inMedium) {
    const auto t = static_cast<float>(flight->t_m);
    const physics::ScatterVertex mediumVertex =
        physics::mediumVertex(tracing.medium.albedo(), tracing.medium.phase, tracing.medium.g);
    const glm::vec3 flux =
        childFlux(parent.vertex, mediumVertex, share, continuation.weight) * flight->weight;
    if (flux.r + flux.g + flux.b > 0.0f) {
      child = mediumVpl(p + w * t, parent.positionPath.w + eta * t, flux, -w, tracing.medium, 0.0f);
    }
    vertex = mediumVertex;
  } else {
    if (!hit) return std::nullopt;  // the light leaves the scene
    float path_m = parent.positionPath.w + eta * glm::length(hit->position_world - p);
    // The child receives the parent's share times the continuation's weight
    // and carries the hit's vertex (and, where its flux does not hold its
    // scatter, the direction its light came from, -w).
    vertex = hitVertex(*hit, vertices);
    glm::vec3 flux = childFlux(parent.vertex, vertex, share, continuation.weight);
    if (flight) {
      flux *= flight->weight;
    } else if (tracing.medium.present()) {
      flux *= physics::mediumTransmittance(tracing.medium.sigmaT(),
                                           glm::length(hit->position_world - p));
    }
    if (regionLeg) {
      // Through the regions to the hit: T / P(reaching it), the transmittance
      // itself where the leg crosses no scattering region (as the first
      // bounce's light legs), and the time it spends in them.
      const double d = glm::length(hit->position_world - p);
      flux *= glm::vec3(regionLeg->passWeight(d));
      path_m += static_cast<float>(static_cast<double>(eta) * regionLeg->extraPath_m(d));
    }
    if (flux.r + flux.g + flux.b > 0.0f) {
      child = Vpl{glm::vec4(hit->position_world, path_m), glm::vec4(hit->normal_world, 0.0f),
                  glm::vec4(flux, 0.0f)};
      child->vertex = vertex;
      if (!physics::vplFluxHoldsScatter(vertex)) child->incoming = glm::vec4(-w, 0.0f);
    }
  }
  if (child && tracing.russian_roulette) {
    // Survival q = the largest albedo (base colour) channel: a survivor's flux / q stays
    // within the share in every channel, and E[flux] is unchanged.
    const float q = std::min(1.0f, std::max({vertex.color.r, vertex.color.g, vertex.color.b}));
    if (!(rng.nextFloat() < q)) return std::nullopt;
    child->flux /= q;
  }
  if (child && materials.classes != nullptr) {
    child->flux.w = vplClassAfter(*materials.classes, vplClassOf(parent), vertex);
  }
  return child;
}

// Rays per task: a fixed split, so that each task writes its own slots.
constexpr std::size_t kRaysPerTask = 256;

}  // namespace

std::vector<Vpl> traceBounce(const rays::RayScene& scene, const std::vector<Vpl>& parents,
                             std::size_t count, int32_t bounce, uint64_t seed,
                             double indexOfRefraction, const BounceTracing& tracing,
                             const BounceMaterials& materials) {
  std::vector<Vpl> children;
  double total = 0.0;
  for (const Vpl& v : parents) total += powerOf(v);
  if (parents.empty() || count == 0 || !(total > 0.0)) return children;
  // Systematic resampling: child j takes the parent whose share of the
  // cumulative power holds (j + offset) * total / count.
  Pcg32 offsetRng = Pcg32::forUnit(seed, unitOf(kOffsetUnit, bounce, 0));
  const double offset = offsetRng.nextDouble();
  const double step = total / static_cast<double>(count);
  std::vector<std::size_t> parentOf(count);
  std::size_t parent = 0;
  double parentEnd = powerOf(parents[0]);
  for (std::size_t j = 0; j < count; ++j) {
    const double target = (static_cast<double>(j) + offset) * step;
    // The last parent also takes any target rounding puts past the total.
    while (target >= parentEnd && parent + 1 < parents.size()) {
      parentEnd += powerOf(parents[++parent]);
    }
    parentOf[j] = parent;
  }
  // Every ray has its own generator and slot: the bytes do not depend on
  // the threads.
  const auto eta = static_cast<float>(indexOfRefraction);
  std::vector<std::optional<Vpl>> slots(count);
  const std::size_t tasks = (count + kRaysPerTask - 1) / kRaysPerTask;
  const int threads = resolveThreads(tracing.threads);
  const std::vector<physics::ScatterVertex> vertices =
      materialVertices(scene.scene(), materials.vertexModel);
  parallelFor(tasks, threads, [&](std::size_t task) {
    const std::size_t end = std::min(count, (task + 1) * kRaysPerTask);
    for (std::size_t j = task * kRaysPerTask; j < end; ++j) {
      const Vpl& from = parents[parentOf[j]];
      const glm::vec3 share = glm::vec3(from.flux) * static_cast<float>(step / powerOf(from));
      slots[j] = shootChild(scene, from, share, bounce, seed, j, eta, tracing, materials, vertices);
    }
  });
  children.reserve(count);
  for (const std::optional<Vpl>& child : slots) {
    if (child) children.push_back(*child);
  }
  return children;
}

namespace {

// withLaterBounces with the scene given, or built here from job.scene (null)
// only when a later bounce is traced.
BouncedVpls traceLaterBounces(const capture::RenderJob& job, const rays::RayScene* given,
                              std::vector<Vpl> firstBounce,
                              const physics::ResponseClassTable* classes) {
  const capture::IndirectSettings& s = job.settings.indirect;
  TOFSIM_CHECK(s.bounces >= 1);
  std::unique_ptr<rays::RayScene> built;
  const auto scene = [&]() -> const rays::RayScene& {
    if (given != nullptr) return *given;
    if (!built) built = std::make_unique<rays::RayScene>(*job.scene, 0);
    return *built;
  };
  const physics::ResponseClassTable* delayed =
      classes != nullptr && classes->delayed() ? classes : nullptr;
  BouncedVpls out;
  out.vpls = std::move(firstBounce);
  // Per-region media: every later leg through the regions (joined with the
  // scene's region meshes here, once per render).
  const capture::MediumRegions regions =
      job.settings.media.empty() ? capture::MediumRegions()
                                 : capture::MediumRegions(job.settings.media, *job.scene,
                                                          job.settings.time.index_of_refraction);
  // A scattering medium: the light's paths that scatter in it before any
  // surface, after the RSM's VPLs (bounce 1: one scattering event); the
  // same in scattering regions.
  if (lightMediumVplsWanted(job.settings)) {
    const auto rays = static_cast<std::size_t>(s.medium_vpls);
    const std::vector<Vpl> medium =
        job.settings.medium.scatters()
            ? lightMediumVpls(scene(), job.light, job.settings.medium, rays, job.settings.seed,
                              job.settings.time.index_of_refraction, s.trace_threads, delayed)
            : lightRegionVpls(scene(), job.light, regions, rays, job.settings.seed,
                              job.settings.time.index_of_refraction, s.trace_threads, delayed);
    out.vpls.insert(out.vpls.end(), medium.begin(), medium.end());
  }
  out.firstOfBounce = {0, out.vpls.size()};
  if (s.bounces == 1 || out.vpls.empty()) {
    out.firstOfBounce.resize(static_cast<std::size_t>(s.bounces) + 1, out.vpls.size());
    return out;
  }
  const std::size_t count =
      s.vpls_per_bounce > 0 ? static_cast<std::size_t>(s.vpls_per_bounce) : out.vpls.size();
  const BounceTracing tracing{s.russian_roulette, s.trace_threads, job.settings.medium, &regions};
  const BounceMaterials materials{vertexModelOf(job.settings.materials),
                                  static_cast<float>(s.vpl_brdf_clamp_per_sr), delayed};
  std::vector<Vpl> parents(out.vpls);
  for (int32_t bounce = 2; bounce <= s.bounces; ++bounce) {
    // Russian roulette ends paths: bounce 3 on traces one ray per VPL kept.
    const std::size_t rays = s.russian_roulette && bounce > 2 ? parents.size() : count;
    parents = traceBounce(scene(), parents, rays, bounce, job.settings.seed,
                          job.settings.time.index_of_refraction, tracing, materials);
    out.vpls.insert(out.vpls.end(), parents.begin(), parents.end());
    out.firstOfBounce.push_back(out.vpls.size());
  }
  return out;
}

}  // namespace

BouncedVpls withLaterBounces(const capture::RenderJob& job, const rays::RayScene& scene,
                             std::vector<Vpl> firstBounce,
                             const physics::ResponseClassTable* classes) {
  return traceLaterBounces(job, &scene, std::move(firstBounce), classes);
}

BouncedVpls withLaterBounces(const capture::RenderJob& job, std::vector<Vpl> firstBounce,
                             const physics::ResponseClassTable* classes) {
  return traceLaterBounces(job, nullptr, std::move(firstBounce), classes);
}

}  // namespace tofsim::ir
