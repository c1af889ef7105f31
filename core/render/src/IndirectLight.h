#pragma once
// One indirect bounce from VPLs on GL. The driver (ir::IrRenderer) processes
// the VPLs in batches whose imperfect shadow maps fit the memory budget
// (Algorithm 1 of the paper); each batch's ISMs are built here, gathered into
// the current segment and dropped. With exact visibility, shadow rays through
// a BVH replace the ISMs.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/scene/TriangleSoup.h"

namespace tofsim::render {

using scene::BvhNode;
using scene::TriangleSoup;

class IndirectLight {
 public:
  /// The gather's variant (pixel samples, footprints, the imager's kind) and
  /// the ISM seed come from the job; foldModel: gpu::gatherDefines';
  /// `responseDefines`: the gather's response classes (GatherResponseClasses::defines).
  IndirectLight(const TriangleSoup& soup, const std::vector<ir::Vpl>& vpls,
                const capture::RenderJob& job, bool foldModel = true,
                const std::vector<std::pair<std::string, std::string>>& responseDefines = {});

  std::size_t vplCount() const { return vplCount_; }
  /// GPU bytes that do not depend on the batch size (geometry, VPLs).
  std::size_t fixedBytes() const { return fixedBytes_; }
  /// GPU bytes of one VPL's ISM with all pull-push levels (0 for exact visibility).
  std::size_t ismBytesPerVpl() const;
  /// Room for the ISMs of `vplsPerBatch` VPLs (none for exact visibility).
  void allocate(std::size_t vplsPerBatch);

  /// Sets the gather program's per-render uniforms (time axis, camera...).
  const gl::Program& gatherProgram() const { return gather_; }
  /// Builds the ISMs of VPLs [firstVpl, firstVpl + count) (no-op for exact).
  void buildVisibility(std::size_t firstVpl, std::size_t count);
  /// Gathers VPLs [firstVpl, firstVpl + count), whose ISMs were built last,
  /// into pixels [firstPixel, firstPixel + pixelCount) of the bound indirect
  /// and outside-axis buffers.
  void gather(std::size_t firstVpl, std::size_t count, std::size_t firstPixel,
              std::size_t pixelCount);
  /// Binds the VPLs and their visibility (the ISMs built last, or the BVH)
  /// for `program`, which reads them through vpl.glsl and vpl_visibility.glsl
  /// (the medium's VPL pass, MediumVpls), its ISM uniforms set; uses it.
  void bindVisibility(const gl::Program& program) const;
  /// Throws where a pass came near llvmpipe's loop-trip limit (its guard flag).
  void checkLoopGuard() const;

 private:
  IndirectLight(const TriangleSoup& soup, const std::vector<ir::Vpl>& vpls,
                const capture::RenderSettings& settings,
                const std::vector<std::pair<std::string, std::string>>& defines);
  void bindSceneBuffers() const;
  /// VPLs one gather dispatch may loop over (see kLoopTripLimit in the shader).
  std::size_t vplsPerDispatch() const;

  capture::IndirectSettings settings_;
  uint64_t seed_;
  std::size_t samplesPerPixel_ = 1;  ///< render.pixel_samples squared
  std::size_t vplCount_ = 0;
  std::size_t triangleCount_ = 0;
  std::size_t tripsPerShadowRay_ = 0;
  /// Per-region media: loop trips of a VPL -> sample leg's passage (0 without).
  std::size_t regionTripsPerLeg_ = 0;
  /// Whether a gather may trace shadow rays: exact visibility, or medium
  /// VPLs (exact whatever the visibility, indirect_gather.comp's visible).
  bool shadowRays_ = false;
  std::size_t fixedBytes_ = 0;
  std::size_t ismFirstVpl_ = 0;  ///< VPL whose ISM starts the ISM buffer
  std::vector<std::size_t> levelOffsets_;
  std::vector<int> levelSizes_;
  std::size_t floatsPerVpl_ = 0;
  gl::Buffer corners_, areaCdf_, bvh_, vplBuffer_, ism_, loopGuard_;
  gl::Program splat_, pull_, push_, gather_;
};

}  // namespace tofsim::render
