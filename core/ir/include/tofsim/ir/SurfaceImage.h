#pragma once
// The first surface seen through each pixel, found by one ray through the
// pixel's centre, or through each of its N x N sub-pixel centres: the surface
// samples every gather reads. The CPU backend traces them for every imager;
// for an imager a rasterizer cannot draw (a point set) the driver traces them
// and hands them to the GL backend (IrBackend::setSurfaces), which lays them
// into its G-buffer textures. Their conventions are the rasterized
// SurfaceMaps' (shaders/gbuffer.frag, read by shaders/surface_samples.glsl):
// world position with w = 1 on a surface and 0 elsewhere, unit normal facing
// the viewpoint, the scattering vertex (albedo and metallic-roughness with
// textures). A sample the driver makes itself may be a medium point
// (physics::VERTEX_MEDIUM: no normal, an isotropic phase function).

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "tofsim/capture/Imager.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::rays {
class RayScene;
}

namespace tofsim::ir {

struct SurfaceImage {
  int32_t width = 0;
  int32_t height = 0;
  /// Pixel p's samples are entries [firstSample[p], firstSample[p + 1]), a
  /// side[p] x side[p] grid of its sub-pixels (side 1: the pixel centre),
  /// each through apertureSamples points of a defocused camera's aperture:
  /// sub-pixel j's are entries j * apertureSamples + a, a the index of
  /// capture::aperturePoint. traceSurfaces gives every pixel the same N,
  /// traceSampledPixels mixes 1 and N.
  std::vector<std::size_t> firstSample;
  std::vector<int32_t> side;
  int32_t apertureSamples = 1;  ///< 1: the pinhole's ray (the aperture's centre)
  /// With apertureSamples > 1, each sample's aperture point (xyz world),
  /// where its camera leg ends, and the lens's path from there to the pixel
  /// less the chief ray's (w, m: capture::ApertureRay::lensPath_m); for an
  /// imager whose rays have their own origins (!capture::raysShareOrigin),
  /// each sample's ray origin (w = 0); empty otherwise (the imager's
  /// viewpoint, no lens path).
  std::vector<glm::vec4> aperture;
  std::vector<glm::vec4> position;  ///< xyz world, w = 1 on a surface, 0 else
  std::vector<glm::vec4> normal;    ///< xyz unit shading normal facing the viewpoint (0: a medium)
  /// What the sample scatters (physics::scatter): its only material member.
  std::vector<physics::ScatterVertex> vertex;
  std::vector<glm::vec3> geometric;  ///< triangle normal facing the viewpoint (ray offsets)

  std::size_t size() const { return position.size(); }
  std::size_t samplesOf(std::size_t pixel) const {
    return firstSample[pixel + 1] - firstSample[pixel];
  }
  /// Where sample i's camera leg ends, and the lens's path it adds.
  glm::vec3 cameraOf(std::size_t i, const glm::vec3& viewpoint) const {
    return aperture.empty() ? viewpoint : glm::vec3(aperture[i]);
  }
  float lensPathOf(std::size_t i) const { return aperture.empty() ? 0.0f : aperture[i].w; }
};

/// The ray traceSurfaces traces for entry e of pixel (x, y), a pixel of
/// `side` x `side` sub-pixels each through `apertureSamples` points of
/// `lens` (null: one, the chief rays), with the lens's path after its origin
/// (0 without a lens). The medium's passes (issue 42) follow it where it
/// meets no surface.
capture::ApertureRay sampleRay(const capture::PrimaryRays& rays, const capture::ThinLens* lens,
                               int32_t x, int32_t y, int32_t side, int32_t apertureSamples,
                               std::size_t e);

/// The imager's G-buffer: pixel (x, y), row 0 at the top, along its primary
/// ray (capture::PrimaryRays; a pinhole's Camera::pixelDirection); with samplesPerSide N > 1, N x N
/// samples per pixel at the centres of its sub-pixels, sub-pixel (i, j) at offset
/// ((i + 1/2) / N - 1/2, (j + 1/2) / N - 1/2), entry j * N + i. With
/// apertureSamples K > 1 (capture::apertureSamplesOf: a defocused camera)
/// each of them K times, from the aperture's points (capture::ThinLens),
/// entry (j * N + i) * K + a; K = 1: the chief rays. Each hit's vertex has
/// the model vertexModel (physics::VERTEX_*: vertexModelOf the render's
/// materials).
SurfaceImage traceSurfaces(const rays::RayScene& scene, const capture::Imager& imager, int threads,
                           int32_t samplesPerSide = 1, int32_t apertureSamples = 1,
                           int vertexModel = physics::VERTEX_LAMBERTIAN);

/// render.adaptive_pixel_samples: N x N samples (as traceSurfaces places
/// them) for the pixels where sampled[p] is 1, the centre's one elsewhere,
/// each through apertureSamples aperture points; only those rays are traced.
SurfaceImage traceSampledPixels(const rays::RayScene& scene, const capture::Imager& imager,
                                int threads, int32_t samplesPerSide,
                                const std::vector<uint8_t>& sampled, int32_t apertureSamples = 1,
                                int vertexModel = physics::VERTEX_LAMBERTIAN);

/// The pixel centres' positions and normals, as prepareSurfaces returns
/// them, of an image of one sample per pixel.
CentreSurfaces centresOf(const SurfaceImage& centres);

}  // namespace tofsim::ir
