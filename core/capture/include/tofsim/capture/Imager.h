#pragma once
// What a capture's pixels look at, whatever renders it: a pinhole camera, or a
// set of points on the scene's surfaces seen from one origin (the relay-wall
// points of a non-line-of-sight scan, or any list of points). Each kind says
// its primary ray per sample, the surface's step across one of its pixels
// (the pixel footprint, pbrt-v4's Approximate_dp_dxy idea) and, for the
// pinhole only, the view-projection a rasterizer can draw its G-buffer with.
// A camera with a calibrated lens is a Camera whose rays and steps come from
// its lens (Camera.h); it is traced, not rasterized. A new kind is one more
// alternative and its functions here.

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tofsim/capture/Camera.h"

namespace tofsim::scene {
struct Scene;
}

namespace tofsim::capture {

/// Points on the scene's surfaces, each one pixel of a width x height image
/// (row-major, row 0 first; an N x 1 image for a plain list), seen from
/// origin_world: a pixel's primary ray runs from the origin towards its
/// point, and its light's last leg from the surface it hits back to the
/// origin (the SPAD or streak camera focused on the point).
struct PointSetImager {
  int32_t width = 0;
  int32_t height = 1;
  std::vector<glm::vec3> points_world;  ///< width * height, row-major
  glm::vec3 origin_world{0.0f};
  /// false: the last leg takes no time, the arrival is timed at the point (y-tal's
  /// account_first_and_last_bounces: false for the wall-to-sensor leg).
  bool last_leg_counts = true;
  /// One pixel's extent on the surface: the step from a point to the next
  /// along its row (u) and down its column (v). Zero: the points are point
  /// samples (the footprint is then a delta, as render.pixel_footprint: false).
  glm::vec3 step_u_world{0.0f};
  glm::vec3 step_v_world{0.0f};
};

struct PrimaryRay {
  glm::vec3 origin;
  glm::vec3 direction;  ///< unit
};

/// Rays of the user's own sensor geometry (a fibre bundle, a scanning
/// pattern, a custom lens), each one pixel of a width x height image
/// (row-major; an N x 1 image for a plain list): a pixel's primary ray is its
/// ray, and its light's last leg runs from the surface the ray hits back to
/// the ray's own origin. A pixel is a point sample: it has no extent, so its
/// footprint is a delta (as render.pixel_footprint: false).
struct RayListImager {
  int32_t width = 0;
  int32_t height = 1;
  std::vector<PrimaryRay> rays;  ///< width * height, row-major, unit directions
  /// false: the last leg takes no time (as PointSetImager::last_leg_counts).
  bool last_leg_counts = true;
};

using Imager = std::variant<Camera, PointSetImager, RayListImager>;

int32_t imageWidth(const Imager& imager);
int32_t imageHeight(const Imager& imager);
/// Where the primary rays start and the last leg ends.
glm::vec3 viewpoint(const Imager& imager);
/// Whether the last leg (surface -> viewpoint) is part of the optical path;
/// render.camera_unwarp drops it for every imager.
bool lastLegCounts(const Imager& imager);
/// The pinhole, or null for an imager a rasterizer cannot draw (a point
/// set, a camera with a lens or an aperture).
const Camera* pinhole(const Imager& imager);
/// The camera, with or without a lens; null for a point set.
const Camera* cameraOf(const Imager& imager);
/// Throws InputError when the imager's own data do not fill its width x
/// height pixels (a point set's points).
void checkLayout(const Imager& imager);
/// Whether each pixel is a point: every primary ray of a pixel is its centre's
/// (a point set without steps), so a pixel filter has nothing to average.
bool pointPixels(const Imager& imager);
/// Whether every primary ray starts at viewpoint(): false for an imager whose
/// rays have their own origins, where each traced sample carries its camera
/// leg's end (ir::SurfaceImage::aperture). A camera's chief rays share its
/// position (its aperture points are sampled apart: ThinLens.h).
bool raysShareOrigin(const Imager& imager);
/// Every point a last leg may end at, once each: viewpoint() when the rays
/// share it (for bounds over the imager's arrivals).
std::vector<glm::vec3> viewpoints(const Imager& imager);
/// What the imager is, as the outputs' metadata name it: "camera",
/// "point_set", "ray_list".
const char* imagerKind(const Imager& imager);

/// Primary rays of an imager, with what they share computed once (a
/// pinhole's frame, as capture::PixelRays, whose directions these are bit for
/// bit).
class PrimaryRays {
 public:
  explicit PrimaryRays(const Imager& imager);
  /// Through the centre of pixel (x, y).
  PrimaryRay ray(int32_t x, int32_t y) const;
  /// Through the point `offset` (pixels, in [-1/2, 1/2]^2, +x right, +y
  /// down) from pixel (x, y)'s centre.
  PrimaryRay ray(int32_t x, int32_t y, glm::vec2 offset) const;

 private:
  const Imager& imager_;
  std::optional<PixelRays> pinholeRays_;
};

/// The surface's steps across one of the imager's pixels (or across a
/// sub-pixel of side `side` pixels): the footprint's dx/du, dx/dv.
struct FootprintSteps {
  glm::vec3 dxdu{0.0f};
  glm::vec3 dxdv{0.0f};
};
class PixelSteps {
 public:
  /// At pixel (x, y): a lens's steps vary across the image (the pinhole's
  /// and a point set's do not, and ignore it).
  PixelSteps(const Imager& imager, float side, int32_t x = 0, int32_t y = 0);
  /// At surface point x with unit normal n.
  FootprintSteps at(const glm::vec3& x, const glm::vec3& n) const;
  /// Same for a camera's ray from `origin`, a point of its aperture
  /// (ThinLens.h): it aims at its pixel's point in focus, which moves across
  /// the pixel as the pinhole's ray does, so the ray steps are the pinhole's
  /// (the aperture lies in the plane through the camera normal to its axis).
  FootprintSteps at(const glm::vec3& x, const glm::vec3& n, const glm::vec3& origin) const;
  /// What `at` starts from, for a device that computes it itself
  /// (footprint_deposit.glsl): a camera's ray steps across the (sub-)pixel,
  /// or a point set's surface steps, which `at` returns as they are.
  bool carriedToSurface() const { return pinhole_; }
  const glm::vec3& stepU() const { return stepX_; }
  const glm::vec3& stepV() const { return stepY_; }

 private:
  bool pinhole_ = false;  ///< a camera's ray steps, with or without a lens
  glm::vec3 origin_{0.0f}, forward_{0.0f};
  glm::vec3 stepX_{0.0f}, stepY_{0.0f};  ///< camera: ray steps; point set: surface steps
};

/// A width x height grid of points at the centres of the cells of the
/// rectangle the node or mesh `meshName` spans in its plane, seen from
/// origin_world: a relay wall's scan points. Its frame is the relay wall's
/// (capture::relayWallOf): columns along the wall's x axis, row 0 at its top
/// (largest y). Throws InputError naming the mesh when it does not exist, is
/// not planar or has no area.
PointSetImager gridOnPlanarMesh(const scene::Scene& scene, const std::string& meshName,
                                int32_t width, int32_t height, const glm::vec3& origin_world,
                                bool lastLegCounts = true);

}  // namespace tofsim::capture
