#include "GatherKernel.h"

#include "GatherRoulette.h"

#include <algorithm>
#include <cmath>

#include "tofsim/physics/FootprintKernel.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/physics/VplNearField.h"

namespace tofsim::cpu {

namespace {

static_assert(kFootprintDirectBins == physics::FOOTPRINT_DIRECT_BINS);

// The footprint kernels of the block's contributions, from the same shared
// functions as indirect_gather.comp: the path's steps across the pixel (the
// gradient of eta (|x - x_l| + |x - c|) on x's steps) and across the VPL's
// patch, combined into one trapezoid.
__attribute__((target_clones("avx2", "default"))) void vplKernels(const PixelSurface& s,
                                                                  const VplArrays& v,
                                                                  std::size_t first, std::size_t n,
                                                                  const GatherConstants& c,
                                                                  VplTerms& __restrict terms) {
  const float eta = c.indexOfRefraction;
  const float vplFootprint = c.vplFootprint ? 1.0f : 0.0f;
  // Plain pointers, read before the loop (as vplTerms): the vectoriser does
  // not see through the vectors' members.
  const float* __restrict px = v.px.data() + first;
  const float* __restrict py = v.py.data() + first;
  const float* __restrict pz = v.pz.data() + first;
  const float* __restrict path = v.path.data() + first;
  const float* __restrict ux = v.ux.data() + first;
  const float* __restrict uy = v.uy.data() + first;
  const float* __restrict uz = v.uz.data() + first;
  const float* __restrict uw = v.uw.data() + first;
  const float* __restrict vx = v.vx.data() + first;
  const float* __restrict vy = v.vy.data() + first;
  const float* __restrict vz = v.vz.data() + first;
  const float* __restrict vw = v.vw.data() + first;
  const glm::vec3 x = s.x, dxdu = s.dxdu, dxdv = s.dxdv, camera = s.camera;
  const float cameraPath = s.cameraPath_m, start = c.start_m, width = c.binWidth_m;
  const bool unwarp = c.cameraUnwarp;
  const bool regions = c.regions != nullptr;
  const int bins = c.bins;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec2 pixel = physics::pathStepsAcrossPixel(
        physics::opticalPathGradient(x, glm::vec3(px[i], py[i], pz[i]), camera, eta, unwarp), dxdu,
        dxdv);
    const glm::vec3 d(terms.dx[i], terms.dy[i], terms.dz[i]);
    // Loaded for every lane and zeroed without the VPL footprint: a
    // conditional load would be a branch, and the loop would not vectorise.
    const glm::vec2 patch =
        vplFootprint * physics::vplPatchPathSteps(glm::vec4(ux[i], uy[i], uz[i], uw[i]),
                                                  glm::vec4(vx[i], vy[i], vz[i], vw[i]), d, eta);
    // Centred on the path regionLanes binned (the regions' delay on the
    // VPL -> x leg; its other legs' are in path and cameraPath).
    const float leg_m = regions ? terms.dist[i] + terms.regionExtra_m[i] : terms.dist[i];
    const float path_m = physics::vplPathLength(path[i], eta, leg_m, cameraPath);
    const glm::vec3 kernel =
        physics::footprintKernel(path_m, glm::vec4(pixel, patch), start, width);
    terms.centre[i] = kernel.x, terms.wide[i] = kernel.y, terms.narrow[i] = kernel.z;
    const NarrowShape shape = narrowShapeOf(kernel);
    terms.frac[i] = shape.frac, terms.last[i] = shape.last;
    terms.perRamps[i] = shape.perRamps, terms.perWide[i] = shape.perWide;
    const bool narrow = physics::footprintIsNarrow(kernel);
    terms.first[i] = physics::footprintNarrowFirstBin(kernel, bins);
    terms.count[i] = narrow ? physics::footprintNarrowBinCount(kernel) : 0;
  }
}

// physics::vplGeometryTerm of VPL k at x, or vplMediumGeometryTerm where x
// is a medium point (no plane to project the near field's patch onto: its
// solid angle instead); cosX is the receiver cosine (PixelSurface::n,
// ::cosineOffset).
float geometryAt(const PixelSurface& s, const VplArrays& v, std::size_t k, float cosVpl, float cosX,
                 float dist2, float clampPerM2) {
  const glm::vec3 vplX(v.px[k], v.py[k], v.pz[k]), patchU(v.ux[k], v.uy[k], v.uz[k]),
      patchV(v.vx[k], v.vy[k], v.vz[k]);
  if (!physics::vertexOnSurface(s.vertex)) {
    return physics::vplMediumGeometryTerm(cosVpl, dist2, clampPerM2, s.x, vplX, patchU, patchV);
  }
  return physics::vplGeometryTerm(cosVpl, cosX, dist2, clampPerM2, s.x, s.n, vplX, patchU, patchV);
}

// The block's radiance where x's scatter depends on the directions or the
// VPLs scatter what they send (a glTF BRDF at either end), contribution by
// contribution as indirect_gather.comp computes every one, from the
// directions and distances vplTerms left in `terms` (lanes that light
// nothing are not read).
void scatteredRadiance(const PixelSurface& s, const VplArrays& v, std::size_t first, std::size_t n,
                       const GatherConstants& c, VplTerms& terms) {
  for (std::size_t i = 0; i < n; ++i) {
    if (terms.bin[i] == kNoLight) continue;
    const std::size_t k = first + i;
    const glm::vec3 d(terms.dx[i], terms.dy[i], terms.dz[i]);
    const glm::vec3 vplN(v.nx[k], v.ny[k], v.nz[k]);
    const glm::vec3 toX = s.x - glm::vec3(v.px[k], v.py[k], v.pz[k]);
    const float dist2 = glm::dot(toX, toX);
    const float g = geometryAt(s, v, k, physics::vplEmitterCosine(vplN, d), s.cosineOffset - glm::dot(s.n, d), dist2,
                               c.geometryClamp);
    const glm::vec3 fVpl = v.scatterToward(k, d, c.vplBrdfClamp);
    const glm::vec3 fCamera = physics::scatter(s.vertex, s.n, -d, s.toCamera).f * s.weight;
    const glm::vec3 radiance =
        physics::vplRadiance(fCamera, fVpl, glm::vec3(v.fr[k], v.fg[k], v.fb[k]), g);
    terms.r[i] = radiance.r, terms.g[i] = radiance.g, terms.b[i] = radiance.b;
  }
}

// |x - x_l|^2 as vplTerms computes it, term by term.
float dist2Of(const PixelSurface& s, const VplArrays& v, std::size_t k) {
  const float tx = s.x.x - v.px[k], ty = s.x.y - v.py[k], tz = s.x.z - v.pz[k];
  return tx * tx + ty * ty + tz * tz;
}

// The near-field lanes lanes[0, m) (indices in the block) whose patch lies
// wholly above the pixel's horizon: g = the patch's projected solid angle
// over its area (vplGeometryTerm's near field, by the same shared steps),
// eight lanes per instruction with AVX2; clipped[j] marks the others, whose
// g the caller takes from vplGeometryTerm itself.
__attribute__((target_clones("avx2", "default"))) void unclippedNearField(
    const PixelSurface& s, const VplArrays& v, std::size_t first, const int32_t* __restrict lanes,
    std::size_t m, float* __restrict g, int32_t* __restrict clipped) {
  const float* __restrict px = v.px.data() + first;
  const float* __restrict py = v.py.data() + first;
  const float* __restrict pz = v.pz.data() + first;
  const float* __restrict ux = v.ux.data() + first;
  const float* __restrict uy = v.uy.data() + first;
  const float* __restrict uz = v.uz.data() + first;
  const float* __restrict vx = v.vx.data() + first;
  const float* __restrict vy = v.vy.data() + first;
  const float* __restrict vz = v.vz.data() + first;
  const glm::vec3 x = s.x, n = s.n;
  for (std::size_t j = 0; j < m; ++j) {
    const int32_t i = lanes[j];
    const glm::vec3 patchU(ux[i], uy[i], uz[i]), patchV(vx[i], vy[i], vz[i]);
    const physics::PatchCorners q =
        physics::patchCornersFrom(x, glm::vec3(px[i], py[i], pz[i]), patchU, patchV);
    clipped[j] = !physics::patchAboveHorizon(q, n);
    g[j] = 0.5f * glm::abs(physics::unclippedEdgeSum(q, n)) /
           glm::length(glm::cross(patchU, patchV));
  }
}

// The lanes in a VPL's near field, which vplTerms gave the point VPL's term:
// the patch's integral instead (vplGeometryTerm), as indirect_gather.comp
// computes it for every pair. The lit ones' indices first; their patches
// above the horizon (most) eight at a time, the clipped ones one by one.
void nearFieldRadiance(const PixelSurface& s, const VplArrays& v, std::size_t first, std::size_t n,
                       const GatherConstants& c, VplTerms& terms) {
  alignas(64) int32_t lanes[kVplBlock];
  std::size_t m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    lanes[m] = static_cast<int32_t>(i);
    m += (terms.bin[i] != kNoLight) & (terms.nearField[i] != 0);
  }
  if (m == 0) return;
  alignas(64) float g[kVplBlock];
  alignas(64) int32_t clipped[kVplBlock];
  // A medium point has no horizon to clip at: every lane one by one
  // (geometryAt).
  const bool onSurface = physics::vertexOnSurface(s.vertex);
  if (onSurface) {
    unclippedNearField(s, v, first, lanes, m, g, clipped);
  } else {
    std::fill_n(clipped, m, 1);
  }
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = static_cast<std::size_t>(lanes[j]), k = first + i;
    float gi = g[j];
    if (clipped[j]) {
      const glm::vec3 d(terms.dx[i], terms.dy[i], terms.dz[i]);
      gi = geometryAt(s, v, k, v.emitterOffset[k] + (v.nx[k] * d.x + v.ny[k] * d.y + v.nz[k] * d.z),
                      s.cosineOffset - (s.n.x * d.x + s.n.y * d.y + s.n.z * d.z), dist2Of(s, v, k),
                      c.geometryClamp);
    }
    terms.r[i] = s.brdf.r * v.fr[k] * gi;
    terms.g[i] = s.brdf.g * v.fg[k] * gi;
    terms.b[i] = s.brdf.b * v.fb[k] * gi;
  }
}

// A medium filling the scene: each lane's radiance times the transmittance
// of its VPL -> x leg and x's camera leg (the light -> VPL leg and the
// earlier ones are in the VPL's flux). After the radiance passes, so each
// lane is attenuated once whichever of them wrote it; lanes that light
// nothing are multiplied too, and never read.
void attenuateLanes(const PixelSurface& s, std::size_t n, const GatherConstants& c,
                    VplTerms& terms) {
  // A grey medium (fog): one exp per lane, the same float as each channel's.
  if (c.sigmaT.r == c.sigmaT.g && c.sigmaT.g == c.sigmaT.b) {
    for (std::size_t i = 0; i < n; ++i) {
      const float t = physics::mediumTransmittance(c.sigmaT, terms.dist[i] + s.cameraLeg_m).r;
      terms.r[i] *= t;
      terms.g[i] *= t;
      terms.b[i] *= t;
    }
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 t = physics::mediumTransmittance(c.sigmaT, terms.dist[i] + s.cameraLeg_m);
    terms.r[i] *= t.r;
    terms.g[i] *= t.g;
    terms.b[i] *= t.b;
  }
}

// Per-region media: each lit lane's VPL -> x leg through the regions (its
// transmittance and the time it adds: the lane's bin again, and the centre of
// its footprint kernel, vplKernels) and x's camera leg's transmittance.
void regionLanes(const PixelSurface& s, const VplArrays& v, std::size_t first, std::size_t n,
                 const GatherConstants& c, VplTerms& terms) {
  for (std::size_t i = 0; i < n; ++i) {
    terms.regionExtra_m[i] = 0.0f;
    if (terms.bin[i] == kNoLight) continue;
    const std::size_t k = first + i;
    const capture::RegionPassage leg =
        c.regions->passage(glm::dvec3(v.px[k], v.py[k], v.pz[k]), glm::dvec3(s.x));
    const glm::vec3 t = glm::vec3(leg.transmittance()) * s.regionCameraT;
    terms.r[i] *= t.r;
    terms.g[i] *= t.g;
    terms.b[i] *= t.b;
    terms.regionExtra_m[i] = static_cast<float>(leg.extraPath_m);
    const float path_m = physics::vplPathLength(
        v.path[k], c.indexOfRefraction, terms.dist[i] + terms.regionExtra_m[i], s.cameraPath_m);
    terms.bin[i] = physics::binOfPath(path_m, c.start_m, c.binWidth_m);
  }
}

}  // namespace

// target_clones: an AVX2 build and a baseline one of the same source, picked
// at load time. -ffp-contract=off (CMakeLists.txt) keeps fused multiply-adds
// out, and -fno-math-errno only lets sqrt vectorise, so both clones compute
// the same correctly rounded IEEE operations and give the same bytes.
namespace {

// vplTerms' lanes, eight per instruction: each VPL's direction, distance,
// geometry term, bin and near field at x; whether any lane is in its VPL's
// near field. Its own function: with the roulette's calls after it in one
// body (GatherRoulette.cpp: another translation unit, `terms` passed out),
// GCC left this loop scalar.
__attribute__((target_clones("avx2", "default"), noinline)) int32_t vplDistances(
    const PixelSurface& s, const VplArrays& v, std::size_t first, std::size_t n,
    const GatherConstants& c, VplTerms& __restrict terms) {
  const float* __restrict px = v.px.data() + first;
  const float* __restrict py = v.py.data() + first;
  const float* __restrict pz = v.pz.data() + first;
  const float* __restrict path = v.path.data() + first;
  const float* __restrict nx = v.nx.data() + first;
  const float* __restrict ny = v.ny.data() + first;
  const float* __restrict nz = v.nz.data() + first;
  const float* __restrict fr = v.fr.data() + first;
  const float* __restrict fg = v.fg.data() + first;
  const float* __restrict fb = v.fb.data() + first;
  const float* __restrict nearLimit = v.nearLimit.data() + first;
  const float* __restrict emitterOffset = v.emitterOffset.data() + first;
  // __restrict and locals: with a run-time alias check per pointer the
  // vectoriser passes its limit of ten and leaves the loop scalar (it did so
  // from the near field on, b100e61).
  const glm::vec3 x = s.x, normal = s.n, brdf = s.brdf;
  const float cosineOffset = s.cosineOffset;  // 1 at a medium point (n = 0), else 0
  const float cameraPath = s.cameraPath_m, eta = c.indexOfRefraction, clamp = c.geometryClamp;
  const float start = c.start_m, width = c.binWidth_m;
  const float offAxis_m = start - 2.0f * width;  // a finite path for dark lanes
  int32_t anyNear = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // The same steps as indirect_gather.comp, lane by lane.
    const float tx = x.x - px[i], ty = x.y - py[i], tz = x.z - pz[i];
    const float dist2 = tx * tx + ty * ty + tz * tz;
    const float dist = std::sqrt(dist2);
    const float dx = tx / dist, dy = ty / dist, dz = tz / dist;
    // physics::vplEmitterCosine: 1 at a medium VPL (no normal, no side).
    const float cosVpl = emitterOffset[i] + (nx[i] * dx + ny[i] * dy + nz[i] * dz);
    const float cosX = cosineOffset - (normal.x * dx + normal.y * dy + normal.z * dz);
    // & rather than &&: no branch, so the loop vectorises.
    const bool lit = (dist2 > 0.0f) & (cosVpl > 0.0f) & (cosX > 0.0f);
    const float g = physics::geometryTerm(cosVpl, cosX, dist2, clamp);
    const float path_m = physics::vplPathLength(path[i], eta, dist, cameraPath);
    const int bin = physics::binOfPath(lit ? path_m : offAxis_m, start, width);
    terms.bin[i] = lit ? bin : kNoLight;
    terms.r[i] = brdf.r * fr[i] * g;
    terms.g[i] = brdf.g * fg[i] * g;
    terms.b[i] = brdf.b * fb[i] * g;
    terms.dx[i] = dx, terms.dy[i] = dy, terms.dz[i] = dz, terms.dist[i] = dist;
    const int32_t near = physics::vplInNearField(dist2, nearLimit[i]);
    terms.nearField[i] = near;
    anyNear |= near;
  }
  return anyNear;
}

}  // namespace

__attribute__((target_clones("avx2", "default"))) void vplTerms(const PixelSurface& s,
                                                                const VplArrays& v,
                                                                std::size_t first, std::size_t n,
                                                                const GatherConstants& c,
                                                                VplTerms& __restrict terms) {
  const int32_t anyNear = vplDistances(s, v, first, n, c, terms);
  // The roulette before the lanes' scalar work (their scattered radiance,
  // near field, visibility and deposit run for the kept lanes only).
  const bool roulette = c.rouletteImportance != nullptr && s.rouletteThreshold > 0.0f;
  if (roulette) roulettePairs(s, c.rouletteImportance, c.rouletteSeed, first, n, terms);
  if (v.scattering || !physics::scatterIsConstant(s.vertex)) {
    scatteredRadiance(s, v, first, n, c, terms);
  } else if (anyNear) {
    nearFieldRadiance(s, v, first, n, c, terms);
  }
  // Tested once per block: without a medium the terms are those of before.
  if (c.medium) attenuateLanes(s, n, c, terms);
  if (c.regions != nullptr) regionLanes(s, v, first, n, c, terms);
  if (roulette) weighKeptPairs(n, terms);
  if (c.footprint) vplKernels(s, v, first, n, c, terms);
}

}  // namespace tofsim::cpu
