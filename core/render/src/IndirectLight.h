#pragma once
// One indirect bounce from VPLs, batched as in Algorithm 1 of the paper: the
// VPLs are processed in batches whose imperfect shadow maps fit the memory
// budget; each batch's ISMs are built, gathered into the current segment and
// dropped. With exact visibility, shadow rays through a BVH replace the ISMs.

#include <cstddef>
#include <vector>

#include "Vpls.h"
#include "tofsim/capture/RenderSettings.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/scene/TriangleSoup.h"

namespace tofsim::render {

using scene::BvhNode;
using scene::TriangleSoup;

struct GatherTarget {
  std::size_t firstPixel = 0;
  std::size_t pixelCount = 0;
};

class IndirectLight {
 public:
  IndirectLight(const TriangleSoup& soup, std::vector<Vpl> vpls,
                const capture::IndirectSettings& settings, uint64_t seed);

  std::size_t vplCount() const { return vplCount_; }
  /// GPU bytes that do not depend on the batch size (geometry, VPLs).
  std::size_t fixedBytes() const { return fixedBytes_; }
  /// GPU bytes of one VPL's ISM with all pull-push levels (0 for exact visibility).
  std::size_t ismBytesPerVpl() const;
  /// Chooses the batch size from the bytes available for ISMs.
  void planBatches(std::size_t ismBudgetBytes, std::size_t maxStorageBlockBytes);
  std::size_t batchCount() const;
  /// GPU bytes of the ISM buffer for one batch (0 for exact visibility).
  std::size_t ismBatchBytes() const { return ism_.size(); }

  /// Sets the gather program's per-render uniforms (time axis, camera...).
  const gl::Program& gatherProgram() const { return gather_; }
  /// Builds batch b's ISMs (when not already resident) and gathers its VPLs
  /// into the bound indirect and outside-axis buffers.
  void gatherBatch(std::size_t batch, const GatherTarget& target);

 private:
  void buildIsms(std::size_t firstVpl, std::size_t count);
  /// VPLs one gather dispatch may loop over (see kLoopTripLimit in the shader).
  std::size_t vplsPerDispatch() const;

  capture::IndirectSettings settings_;
  uint64_t seed_;
  std::size_t vplCount_ = 0;
  std::size_t triangleCount_ = 0;
  std::size_t tripsPerShadowRay_ = 0;
  std::size_t fixedBytes_ = 0;
  std::size_t vplsPerBatch_ = 0;
  std::size_t residentBatch_ = static_cast<std::size_t>(-1);
  std::vector<std::size_t> levelOffsets_;
  std::vector<int> levelSizes_;
  std::size_t floatsPerVpl_ = 0;
  gl::Buffer corners_, areaCdf_, bvh_, vplBuffer_, ism_, loopGuard_;
  gl::Program splat_, pull_, push_, gather_;
};

}  // namespace tofsim::render
