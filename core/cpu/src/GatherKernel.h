#pragma once
// The indirect gather's inner loops for one pixel and one block of VPLs, in
// two passes: `vplTerms` evaluates the shared physics for every VPL of the
// block with no data-dependent control flow (compiled for AVX2 and for the
// baseline ISA, chosen at load time; the compiler vectorises it, 8 VPLs per
// instruction with AVX2), then the caller's scalar pass tests visibility and
// adds each term to its bin in increasing VPL index. Splitting the passes is
// what lets the arithmetic vectorise: the histogram update is a scatter with
// conflicts, which SIMD cannot do faster.

#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "VplArrays.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/physics/FootprintKernel.h"
#include "tofsim/physics/ScatterVertex.h"

namespace tofsim::cpu {

constexpr std::size_t kVplBlock = 256;    ///< VPLs per block: ~10 KiB of VPL data, in L1
constexpr int32_t kNoLight = INT_MIN;     ///< bin of a VPL that does not light the pixel
constexpr int kFootprintDirectBins = 16;  ///< = FOOTPRINT_DIRECT_BINS (checked in GatherKernel.cpp)

/// The camera G-buffer of one pixel, as the gather needs it.
struct PixelSurface {
  glm::vec3 x{0.0f};  ///< world position, m
  /// Unit normal facing the camera; 0 for a medium point
  /// (physics::receiverNormal), whose receiver cosine is cosineOffset.
  glm::vec3 n{0.0f};
  /// physics::receiverCosineOffset: the receiver cosine toward unit w is
  /// cosineOffset + dot(n, w) (1 in a medium, n . w on a surface), with no
  /// branch per VPL.
  float cosineOffset = 0.0f;
  /// Where the vertex's scatter is constant (physics::scatterIsConstant: a
  /// Lambertian surface, albedo / pi), its f times the sample's weight
  /// 1 / N^2: the factor the vectorised pass multiplies by.
  glm::vec3 brdf{0.0f};
  float cameraPath_m = 0.0f;  ///< eta * (|x - c| + lensPath_m), or 0 when unwarped
  /// |x - c|: the camera leg's geometric length in a medium filling the
  /// scene, whatever the unwarp (the lens's path is inside the camera).
  float cameraLeg_m = 0.0f;
  /// c: where the camera leg ends, the viewpoint or the sample's aperture point.
  glm::vec3 camera{0.0f};
  float lensPath_m = 0.0f;  ///< a thin lens's path from c on (SurfaceImage::lensPathOf)
  glm::vec3 dxdu{0.0f};     ///< x's steps across the (sub-)pixel (surfaceStepAcrossPixel)
  glm::vec3 dxdv{0.0f};
  physics::ScatterVertex vertex{};  ///< what x scatters (physics::scatter)
  glm::vec3 toCamera{0.0f};         ///< unit, x -> camera
  /// Per-region media (GatherConstants::regions): the camera leg's
  /// transmittance through their regions and the path it adds to the time
  /// (capture::RegionPassage::extraPath_m, in cameraPath_m already).
  glm::vec3 regionCameraT{1.0f};
  float regionCameraExtra_m = 0.0f;
  float weight = 1.0f;              ///< the sample's share of the pixel, 1 / N^2
  /// render.indirect.gather_pairs (GatherRoulette.h): the sample's roulette
  /// threshold (0: every pair kept) and its index in the render (its draws).
  float rouletteThreshold = 0.0f;
  uint32_t rouletteSample = 0;
};

/// What the time axis and the job fix for every contribution.
struct GatherConstants {
  float start_m = 0.0f;
  float binWidth_m = 1.0f;
  float indexOfRefraction = 1.0f;
  float geometryClamp = 0.0f;  ///< <= 0: no clamp
  bool footprint = false;      ///< compute the footprint kernels (render.pixel_footprint)
  bool vplFootprint = false;   ///< include the VPL patch's widths (render.indirect.vpl_footprint)
  bool cameraUnwarp = false;
  float vplBrdfClamp = 0.0f;  ///< 1/sr, <= 0: no clamp (physics::vplScatter)
  int32_t bins = 0;           ///< of the time axis
  /// A medium fills the scene (capture::Medium::present): every term is
  /// attenuated over its VPL -> x and x -> camera legs by sigmaT.
  bool medium = false;
  glm::vec3 sigmaT{0.0f};  ///< 1/m, per channel
  /// Per-region media (issue 42's `media:`); null without.
  const capture::MediumRegions* regions = nullptr;
  /// render.indirect.gather_pairs (GatherRoulette.h): each VPL's roulette
  /// importance and the draws' seed; null: every pair gathered.
  const float* rouletteImportance = nullptr;
  uint32_t rouletteSeed = 0;
};

/// Per-VPL terms of one block: bin (kNoLight when the VPL does not face the
/// pixel or vice versa), rgb radiance, the unit direction and distance
/// VPL -> x for the visibility test, and with the footprint its kernel
/// (footprintKernel: centre, wide, narrow, in bins).
struct VplTerms {
  alignas(64) int32_t bin[kVplBlock];
  alignas(64) float centre[kVplBlock], wide[kVplBlock], narrow[kVplBlock];
  /// A narrow kernel's bins (footprintNarrowFirstBin, footprintNarrowBinCount;
  /// count 0 for a wide kernel); the deposit computes their masses
  /// (FootprintDeposit.h).
  alignas(64) int32_t first[kVplBlock], count[kVplBlock];
  alignas(64) float r[kVplBlock], g[kVplBlock], b[kVplBlock];
  alignas(64) float dx[kVplBlock], dy[kVplBlock], dz[kVplBlock], dist[kVplBlock];
  /// Per-region media only (GatherConstants::regions): the path the VPL -> x
  /// leg's regions add (capture::RegionPassage::extraPath_m), for the
  /// footprint kernel's centre; 0 for a dark lane.
  alignas(64) float regionExtra_m[kVplBlock];
  /// Whether the pixel lies in the VPL's near field (physics::vplInNearField),
  /// where its geometry term is the patch's integral.
  alignas(64) int32_t nearField[kVplBlock];
  /// With the footprint, each lane's NarrowShape (a narrow kernel's values
  /// for its deposit), computed eight lanes per instruction with the kernel.
  alignas(64) float frac[kVplBlock], last[kVplBlock], perRamps[kVplBlock], perWide[kVplBlock];
  /// With render.indirect.gather_pairs: a kept lane's weight 1 / q (0 dropped).
  alignas(64) float kept[kVplBlock];
};

/// What a narrow footprint kernel's bin masses need besides the kernel
/// (footprintNarrowEdgeCdf's and footprintNarrowCdf's values, with the same
/// float operations): the first kink's position in its bin, the last edge
/// below 1, and the two reciprocals. Per lane in vplKernels' vector pass, so
/// the deposit's scalar part has no division left.
struct NarrowShape {
  float frac, last, perRamps, perWide;
};

inline NarrowShape narrowShapeOf(const glm::vec3& kernel) {
  const float wide = kernel.y, narrow = kernel.z;
  const glm::vec2 e = physics::footprintLocalExtent(kernel);
  return {e.x - std::floor(e.x), std::floor(e.y) - std::floor(e.x), 1.0f / (2.0f * wide * narrow),
          1.0f / wide};
}

/// Fills terms[0, n) for VPLs [first, first + n), n <= kVplBlock: the
/// radiance scatter()'s f at x (per contribution where it is not constant)
/// times what the VPL sends (physics::vplRadiance).
void vplTerms(const PixelSurface& s, const VplArrays& v, std::size_t first, std::size_t n,
              const GatherConstants& c, VplTerms& terms);

}  // namespace tofsim::cpu
