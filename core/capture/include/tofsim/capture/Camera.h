#pragma once
// A pinhole camera, or a calibrated one with a lens (OpenCV's camera matrix
// and distortion, Lens.h). Pixel (x, y) with y = 0 at the top of the image
// looks through the centre of its pixel; all distances are metres in world
// space. With a lens each pixel's ray is the undistorted direction of its
// centre, and a rasterizer cannot draw the image (capture::pinhole is null):
// renderers trace it; so with an aperture (defocus, ThinLens.h).

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

#include "tofsim/capture/Lens.h"

namespace tofsim::capture {

struct Camera {
  glm::vec3 position_world{0.0f};
  glm::vec3 look_at_world{0.0f, 0.0f, -1.0f};
  glm::vec3 up_world{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 40.0f;  ///< full vertical field of view (no lens)
  int32_t width = 64;
  int32_t height = 64;
  /// The calibrated lens, in place of fov_y_deg; none: the ideal pinhole.
  std::optional<Lens> lens;
  /// Thin-lens defocus (ThinLens.h): the aperture's diameter, m (0: a
  /// pinhole, every ray from position_world); the distance along the
  /// optical axis of the plane in focus, m; the aperture points each pixel
  /// sample traces. A defocused camera is traced, not rasterized.
  float aperture_m = 0.0f;
  float focus_distance_m = 1.0f;
  int32_t aperture_samples = 16;

  bool defocused() const { return aperture_m > 0.0f; }

  glm::vec3 forward() const;
  glm::vec3 right() const;
  glm::vec3 up() const;  ///< orthogonalised
  /// Unit world-space direction through the centre of pixel (x, y).
  glm::vec3 pixelDirection(int32_t x, int32_t y) const;
  /// Unit direction through the point `offset` (pixels, in [-1/2, 1/2]^2, +x
  /// right, +y down) from pixel (x, y)'s centre.
  glm::vec3 pixelDirection(int32_t x, int32_t y, glm::vec2 offset) const;
  /// Change of the unnormalised ray direction forward + s right + t up from
  /// one pixel to the next: along +x (right) and along +y (down the image).
  /// The ray differentials of the pixel footprint (footprint_kernel.md).
  /// With a lens, the steps at the image centre; rayStepsAt gives each pixel's.
  glm::vec3 rayStepAlongX() const;
  glm::vec3 rayStepAlongY() const;
  /// The two steps at pixel (x, y): the pinhole's everywhere; with a lens,
  /// the derivative of its undistorted ray (the pixel as the lens distorts it).
  struct RaySteps {
    glm::vec3 alongX{0.0f}, alongY{0.0f};
  };
  RaySteps rayStepsAt(int32_t x, int32_t y) const;
  /// Solid angle (sr) seen by pixel (x, y).
  double pixelSolidAngle_sr(int32_t x, int32_t y) const;
  /// Pixel containing the world point, or (-1, -1) when it projects outside
  /// the image or lies behind the camera.
  glm::ivec2 project(const glm::vec3& point_world) const;
  /// Where the world point lands on the image, in pixels: +x right, +y
  /// down, pixel (x, y)'s centre at (x, y) (OpenCV's convention; through
  /// the lens's distortion when there is one). None behind the camera; a
  /// point outside the image lands outside [-1/2, width - 1/2) x [..).
  std::optional<glm::dvec2> imagePoint(const glm::vec3& point_world) const;

  glm::mat4 view() const;
  /// OpenGL projection with rows flipped so that GL row 0 is image row 0 (top).
  glm::mat4 projection(float near_m, float far_m) const;
};

/// Camera::pixelDirection for many rays (a path tracer's, a G-buffer's): the
/// camera's frame and image-plane scale computed once instead of per ray, by
/// the same float operations, so the directions have the same bits.
class PixelRays {
 public:
  explicit PixelRays(const Camera& camera);
  glm::vec3 direction(int32_t x, int32_t y) const;
  glm::vec3 direction(int32_t x, int32_t y, glm::vec2 offset) const;
  /// Image-plane coordinates at unit distance of pixel position (x, y),
  /// pixel centres at integers (+x right, +y up); with a lens, undistorted.
  glm::dvec2 planePoint(double x, double y) const;

 private:
  glm::vec3 towards(double x, double y) const;

  std::optional<Lens> lens_;
  glm::vec3 forward_, right_, up_;
  double tanHalf_ = 0.0;  ///< tan(fov_y / 2): the image plane's half height at unit distance
  double aspect_ = 1.0;
  int32_t width_ = 1, height_ = 1;
};

}  // namespace tofsim::capture
