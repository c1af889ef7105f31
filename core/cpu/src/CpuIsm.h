#pragma once
// Imperfect shadow maps on the CPU, the same as the GL's (ism_splat.comp,
// ism_pull.comp, ism_push.comp, and the test in indirect_gather.comp): each
// VPL's points are drawn with the same seeded hashes (shaders/random.glsl,
// compiled as C++) from the same area CDF over the same BVH-ordered triangle
// soup, splatted by minimum distance into the same paraboloid texels, and the
// holes filled by the same pull-push. The maps are therefore equal to the
// GPU's up to float rounding of the sampled points (sqrt, products), which can
// move a point across a texel edge.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "GatherKernel.h"
#include "tofsim/capture/RenderSettings.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/scene/Scene.h"
#include "tofsim/scene/TriangleSoup.h"

namespace tofsim::cpu {

class CpuIsm {
 public:
  CpuIsm(const scene::Scene& scene, const std::vector<ir::Vpl>& vpls,
         const capture::IndirectSettings& settings, uint64_t seed);

  std::size_t bytesPerVpl() const { return floatsPerVpl_ * sizeof(float); }
  /// Triangle soup and CDF, held for the whole render.
  std::size_t fixedBytes() const;
  void allocate(std::size_t vplsPerBatch);
  /// Splats and fills the maps of VPLs [firstVpl, firstVpl + count).
  void build(std::size_t firstVpl, std::size_t count, int threads);
  /// Whether VPL `vpl` (of the built batch) sees the point at `dist` along
  /// unit `d`: indirect_gather.comp's test, one pair at a time. The gather
  /// uses cullHidden; this is the recipe IsmCullTest holds it to.
  /// `receiverNormal`, `receiverCosineOffset`: the lit point's
  /// (PixelSurface::n, ::cosineOffset): its receiver cosine sets the
  /// tolerance's slope (ismDepthBias), none for a medium point (cosine 1).
  bool visible(std::size_t vpl, const glm::vec3& d, float dist, const glm::vec3& receiverNormal,
               float receiverCosineOffset, float sceneScale_m) const;
  /// visible() for the n lanes of a block of VPLs [first, first + n) at once:
  /// a lane the map hides gets bin kNoLight. The same float operations, eight
  /// lanes per instruction with AVX2 (the map reads a gather).
  void cullHidden(std::size_t first, std::size_t n, float sceneScale_m,
                  const glm::vec3& receiverNormal, float receiverCosineOffset,
                  VplTerms& terms) const;
  /// The finest level of VPL `vpl`'s map (resolution^2 floats, +inf = empty).
  const float* map(std::size_t vpl) const { return &maps_[(vpl - firstVpl_) * floatsPerVpl_]; }

 private:
  glm::vec3 samplePoint(uint32_t h0, uint32_t h1, uint32_t h2) const;
  void splat(std::size_t vpl, float* map) const;
  void pullPush(float* map) const;

  scene::TriangleSoup soup_;
  std::vector<glm::vec3> vplPosition_, vplNormal_;
  /// Each VPL's basisAround(normal) as arrays for cullHidden's lanes:
  /// tangent t, bitangent b and the normal n (vplNormal_ again, in columns).
  std::vector<float> tx_, ty_, tz_, bx_, by_, bz_, nx_, ny_, nz_;
  capture::IndirectSettings settings_;
  uint32_t seed32_ = 0;
  std::vector<std::size_t> levelOffsets_;
  std::vector<int> levelSizes_;
  std::size_t floatsPerVpl_ = 0;
  std::size_t firstVpl_ = 0, builtCount_ = 0;
  std::vector<float> maps_;
};

}  // namespace tofsim::cpu
