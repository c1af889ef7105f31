#pragma once
// The narrow interface between the backend-independent transient instant
// radiosity driver (ir::IrRenderer: validation, memory plan, segment x VPL
// batch loop, the light seen by the camera) and a device that computes the
// passes. The GL backend (render::GlBackend) implements it; a CPU backend
// implements the same and reuses all of the planning.
//
// Call order: setScene once per scene (IrRenderer::render calls it when the
// job's scene is not the one set last, or after IrRenderer::sceneChanged),
// then per render (IrRenderer::render):
//   limits, [setSurfaces: an imager that cannot be rasterized, on a backend
//   that does not trace rays], prepareSurfaces, [setSampledPixels: render.adaptive_pixel_samples
//   with pixel_samples > 1 only], generateVpls, setVpls, fixedBytes,
//   visibilityBytesPerVpl, allocate, then for each segment (increasing pixel
//   ranges): beginSegment, gatherDirect, for each VPL batch b (increasing):
//   buildVisibility (only when batch b is not already resident: with one batch
//   it is built once for the whole render), gatherIndirect; readSegment.
//   With render.indirect.bounces > 1 the batches are planned within each
//   bounce's VPL range and every bounce but the last ends with takeIndirect
//   (that bounce's light, read out and restarted from zero); the last
//   bounce's light comes with readSegment. One read-back per bounce.
//
// What every implementation must guarantee:
//  - Determinism: the same job gives the same bytes whatever the thread count,
//    scheduling or the segment / batch plan. Every (pixel, bin) has ONE writer,
//    which adds contributions in increasing VPL index; batches arrive in
//    increasing order; off-axis sums are added in pixel order.
//  - The physics is the shared per-contribution math (geometry term with
//    clamp, path length, bin of a path, Lambertian direct term, spot profile),
//    so backends agree.
//  - gatherDirect / gatherIndirect touch only the current segment's pixels.
//  - Volumes have capture::kChannels channels; layout pixel-major, then bin,
//    then channel.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "tofsim/capture/IrCapabilities.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::rays {
class RayScene;
}

namespace tofsim::ir {

struct SurfaceImage;

/// The device's limits the plan and the validation respect.
struct DeviceLimits {
  int32_t maxImageSide = 0;  ///< largest G-buffer / RSM / shadow-map side (GL: max texture size)
  std::size_t maxBufferBytes = 0;    ///< largest single buffer (GL: max storage block); one
                                     ///< pixel's histogram and one VPL's visibility map must fit
  std::size_t maxPixelsPerPass = 0;  ///< most pixels one gather call may cover (GL: groups x 64)
};

/// A virtual point light; layout = struct Vpl in shaders/vpl.glsl (std430,
/// asserted below), whose last two members (`incoming` and `vertex`) the GL
/// backend uploads only where a VPL's scatter is not in its flux
/// (render.materials: gltf): otherwise the first kLambertianVplBytes of each,
/// so the Lambertian gather reads what it did before.
struct Vpl {
  glm::vec4 positionPath;  ///< xyz world, w = optical path light -> VPL, m (eta included)
  glm::vec4 normal;        ///< xyz unit, lit side
  /// rgb: where physics::vplFluxHoldsScatter(vertex) (Lambertian): albedo *
  /// Phi / pi, W/sr (the cosine emitter's intensity); otherwise Phi, W, the
  /// power the VPL received (physics::vplScatter turns it into intensity).
  glm::vec4 flux;
  /// The VPL's patch (its RSM texel on the surface), for the VPL footprint:
  /// xyz = the surface point's step across one texel along the RSM view's
  /// right (patchU) and up (patchV) axes, w = eta (x_l - l)/|x_l - l| . xyz,
  /// the light leg's change of path along it (vplPatchPathSteps).
  glm::vec4 patchU{0.0f};
  glm::vec4 patchV{0.0f};
  /// xyz: unit direction from the VPL toward where its light came from (the
  /// light, or the parent VPL of a later bounce); w: 0. Zero where the
  /// vertex's scatter is in the flux.
  glm::vec4 incoming{0.0f};
  /// The surface point the VPL stands on: its BRDF, its temporal response.
  physics::ScatterVertex vertex{};
};
static_assert(sizeof(Vpl) == 128 && offsetof(Vpl, vertex) == 96, "Vpl: std430 layout of vpl.glsl");

/// The model (physics::VERTEX_*) of every surface vertex of a render with
/// `materials` (render.materials).
inline int vertexModelOf(capture::MaterialModel materials) {
  return materials == capture::MaterialModel::Gltf ? physics::VERTEX_GLTF
                                                   : physics::VERTEX_LAMBERTIAN;
}

/// The camera G-buffer at the pixel centres, as prepareSurfaces returns it:
/// RGBA floats per pixel, row-major, row 0 at the top.
struct CentreSurfaces {
  std::vector<float> positions;  ///< xyz world, w = 1 on a surface, 0 else
  std::vector<float> normals;    ///< xyz unit shading normal facing the camera, w = 0
};

/// Bytes of a VPL as the Lambertian gathers read it (Vpl without incoming
/// and vertex).
constexpr std::size_t kLambertianVplBytes = 5 * sizeof(glm::vec4);

class IrBackend {
 public:
  virtual ~IrBackend() = default;
  /// The device, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" or "CPU (2 threads)".
  virtual std::string description() const = 0;
  virtual DeviceLimits limits() const = 0;
  /// Whether the backend traces the scene with Embree rays (setScene then
  /// gets the driver's RayScene; otherwise the driver builds none unless a
  /// later bounce needs it).
  virtual bool tracesRays() const { return false; }
  /// What the backend gathers beyond the common work (capture/IrCapabilities.h:
  /// a defocused camera's aperture samples, each sample's camera leg ending on
  /// its own aperture point, SurfaceImage::origin; merged pixel samples); the
  /// driver refuses a job that needs more. Default: the GL backend's, none.
  virtual capture::IrCapabilities capabilities() const { return capture::kGlCapabilities; }
  /// The scene every following render sees, prepared once (GL: geometry
  /// upload and the triangle soup's BVH; CPU: nothing but the reference):
  /// `rays` is the driver's one Embree scene of it when tracesRays(), which
  /// the CPU backend traces with and the driver traces later bounces with,
  /// null otherwise. Both must outlive the renders that use them; a new call
  /// replaces them.
  virtual void setScene(const scene::Scene& scene, const rays::RayScene* rays) = 0;
  /// The response classes of the following renders (issue 41; the driver
  /// builds them from the scene's materials, ir::materialResponses): class c
  /// >= 1 gets its own buffer per pixel, filtered by the cascade of its
  /// members' kernels at the integrate step. None (the default table): every
  /// light instant, nothing allocated.
  virtual void setResponseClasses(const physics::ResponseClassTable& classes) = 0;
  /// One capture of the scene set last: camera G-buffer of every pixel
  /// (every sub-pixel sample), light shadow map. Returns the pixel centres'
  /// G-buffer: the driver derives the depth image, the DirectLightView and
  /// the adaptive samples' edge pixels from it. Starts a new render: drops
  /// any earlier render's state (not the scene's).
  virtual CentreSurfaces prepareSurfaces(const capture::RenderJob& job) = 0;
  /// Only for an imager a rasterizer cannot draw (capture::pinhole is null)
  /// on a backend that does not trace rays, right before prepareSurfaces:
  /// the surface samples the driver traced with its RayScene (traceSurfaces
  /// at render.pixel_samples N) and, with N > 1, the pixel centres' (N = 1;
  /// null otherwise), kept for prepareSurfaces, which takes them instead of
  /// rasterizing.
  virtual void setSurfaces(std::unique_ptr<SurfaceImage> samples,
                           std::unique_ptr<SurfaceImage> centres) = 0;
  /// render.adaptive_pixel_samples with render.pixel_samples N > 1 only,
  /// right after prepareSurfaces: one entry per pixel (row-major, row 0 at
  /// the top), 1 where the pixel takes its N x N sub-pixel samples, 0 where it
  /// takes one sample at its centre with weight 1 and the whole pixel's
  /// footprint, as render.pixel_samples: 1 computes it. Without this call
  /// every pixel takes the N x N samples.
  virtual void setSampledPixels(const std::vector<uint8_t>& sampled) = 0;
  /// VPLs of the job's light from the reflective shadow map, in texel order
  /// (faces +X..-Z), empty when indirect light is off or nothing is lit.
  virtual std::vector<Vpl> generateVpls(const capture::RenderJob& job) = 0;
  /// Makes all VPLs resident for the gathers (visibility structures are built
  /// per batch later): those of generateVpls followed by the later bounces'
  /// the driver traced from them (BounceVpls.h). An empty list means no
  /// indirect light this render.
  virtual void setVpls(const std::vector<Vpl>& vpls) = 0;
  /// Bytes held for the whole render (scene, G-buffer, shadow map, VPLs,
  /// BVH...), for the plan.
  virtual std::size_t fixedBytes() const = 0;
  /// Bytes of one VPL's visibility structure (ISM with pull-push levels); 0
  /// for exact visibility (then every VPL is in one batch).
  virtual std::size_t visibilityBytesPerVpl() const = 0;
  /// Room for segments of `pixelsPerSegment` pixels and batches of
  /// `vplsPerBatch` visibility maps (vplsPerBatch = 0 without VPLs).
  virtual void allocate(std::size_t pixelsPerSegment, std::size_t vplsPerBatch) = 0;
  /// Builds the visibility structures of VPLs [firstVpl, firstVpl + count)
  /// (no-op for exact visibility).
  virtual void buildVisibility(std::size_t firstVpl, std::size_t count) = 0;
  /// Zeroes the accumulators of pixels [firstPixel, firstPixel + count).
  virtual void beginSegment(std::size_t firstPixel, std::size_t count) = 0;
  virtual void gatherDirect() = 0;
  /// Adds VPLs [firstVpl, firstVpl + count) (whose visibility was built last)
  /// into the segment.
  virtual void gatherIndirect(std::size_t firstVpl, std::size_t count) = 0;
  /// Copies the indirect light gathered since beginSegment or the last
  /// takeIndirect out (count * bins * kChannels floats, wide footprint kernels
  /// integrated) and zeroes the indirect accumulators; direct light and the
  /// off-axis sums stay as they are (they are read once, by readSegment).
  virtual void takeIndirect(float* indirect) = 0;
  /// Copies the segment out: direct and indirect, count * bins * kChannels
  /// floats each (pixel-major, then bin, then channel), and adds the light
  /// that fell before / after the axis to `offAxis`, pixel by pixel in pixel
  /// order (so the double sums do not depend on the segment plan). What the
  /// accumulators hold afterwards is unspecified until the next beginSegment
  /// (the CPU backend zeroes them as it copies, so beginSegment need not).
  virtual void readSegment(float* direct, float* indirect, AxisLoss& offAxis) = 0;
};

}  // namespace tofsim::ir
