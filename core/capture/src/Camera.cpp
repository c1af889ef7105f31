#include "tofsim/capture/Camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "tofsim/util/Error.h"

namespace tofsim::capture {

glm::vec3 Camera::forward() const { return glm::normalize(look_at_world - position_world); }
glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), up_world)); }
glm::vec3 Camera::up() const { return glm::cross(right(), forward()); }

namespace {
// tan(fov_y / 2): the image plane's half height at unit distance.
double tanHalfFovY(const Camera& c) {
  return std::tan(glm::radians(static_cast<double>(c.fov_y_deg)) * 0.5);
}

}  // namespace

PixelRays::PixelRays(const Camera& camera)
    : lens_(camera.lens),
      forward_(camera.forward()),
      right_(camera.right()),
      up_(camera.up()),
      tanHalf_(tanHalfFovY(camera)),
      aspect_(static_cast<double>(camera.width) / camera.height),
      width_(camera.width),
      height_(camera.height) {}

glm::dvec2 PixelRays::planePoint(double x, double y) const {
  if (lens_) {
    // OpenCV's frame has +y down; the plane's v is up.
    glm::dvec2 ideal;
    const bool inverted = undistortNormalised(*lens_, pixelToNormalised(*lens_, {x, y}), ideal);
    TOFSIM_CHECK(inverted);  // checkLensInvertible ran on the configured image
    return {ideal.x, -ideal.y};
  }
  const double u = (2.0 * (x + 0.5) / width_ - 1.0) * tanHalf_ * aspect_;
  const double v = (1.0 - 2.0 * (y + 0.5) / height_) * tanHalf_;
  return {u, v};
}

glm::vec3 PixelRays::towards(double x, double y) const {
  const glm::dvec2 p = planePoint(x, y);
  return glm::normalize(forward_ + static_cast<float>(p.x) * right_ +
                        static_cast<float>(p.y) * up_);
}

glm::vec3 PixelRays::direction(int32_t x, int32_t y) const { return towards(x, y); }

glm::vec3 PixelRays::direction(int32_t x, int32_t y, glm::vec2 offset) const {
  return towards(x + static_cast<double>(offset.x), y + static_cast<double>(offset.y));
}

glm::vec3 Camera::pixelDirection(int32_t x, int32_t y) const {
  return PixelRays(*this).direction(x, y);
}

glm::vec3 Camera::pixelDirection(int32_t x, int32_t y, glm::vec2 offset) const {
  return PixelRays(*this).direction(x, y, offset);
}

glm::vec3 Camera::rayStepAlongX() const {
  if (lens) return rayStepsAt(width / 2, height / 2).alongX;
  const double tanHalf = tanHalfFovY(*this);
  return right() * static_cast<float>(2.0 * tanHalf / height);  // square pixels
}

glm::vec3 Camera::rayStepAlongY() const {
  if (lens) return rayStepsAt(width / 2, height / 2).alongY;
  const double tanHalf = tanHalfFovY(*this);
  return -up() * static_cast<float>(2.0 * tanHalf / height);
}

namespace {
// d(ideal normalised) / d(pixel) of a lens at pixel (x, y): the inverse of
// the distortion's Jacobian over the camera matrix.
glm::dmat2 idealPerPixel(const Lens& lens, double x, double y) {
  glm::dvec2 ideal;
  TOFSIM_CHECK(undistortNormalised(lens, pixelToNormalised(lens, {x, y}), ideal));
  return glm::inverse(distortionJacobian(lens, ideal)) *
         glm::dmat2(glm::dvec2(1.0 / lens.fx, 0.0), glm::dvec2(0.0, 1.0 / lens.fy));
}
}  // namespace

Camera::RaySteps Camera::rayStepsAt(int32_t x, int32_t y) const {
  if (!lens) return {rayStepAlongX(), rayStepAlongY()};
  // The unnormalised ray forward + x_n right - y_n up: its steps are the
  // columns of d(x_n, y_n) / d(pixel), OpenCV's y down being -up.
  const glm::dmat2 d = idealPerPixel(*lens, x, y);
  const glm::vec3 r = right(), u = up();
  return {static_cast<float>(d[0].x) * r - static_cast<float>(d[0].y) * u,
          static_cast<float>(d[1].x) * r - static_cast<float>(d[1].y) * u};
}

double Camera::pixelSolidAngle_sr(int32_t x, int32_t y) const {
  // A pixel of area dA on the unit-distance plane subtends dA cos^3(theta);
  // through a lens dA is the distorted pixel's, |det d(ideal) / d(pixel)|.
  const double tanHalf = tanHalfFovY(*this);
  const double pixelSide = 2.0 * tanHalf / height;
  const double area =
      lens ? std::fabs(glm::determinant(idealPerPixel(*lens, x, y))) : pixelSide * pixelSide;
  const glm::dvec2 p = PixelRays(*this).planePoint(x, y);
  const double r2 = 1.0 + p.x * p.x + p.y * p.y;
  return area / (r2 * std::sqrt(r2));
}

namespace {
// The pinhole's image-plane coordinates in [-1, 1] (+u right, +v up) of the
// offset d from the camera, z = its depth along the axis.
glm::dvec2 pinholeUv(const Camera& camera, const glm::vec3& d, float z) {
  const double tanHalf = tanHalfFovY(camera);
  const double aspect = static_cast<double>(camera.width) / camera.height;
  return {glm::dot(d, camera.right()) / z / (tanHalf * aspect),
          glm::dot(d, camera.up()) / z / tanHalf};
}
}  // namespace

std::optional<glm::dvec2> Camera::imagePoint(const glm::vec3& point) const {
  const glm::vec3 d = point - position_world;
  const float z = glm::dot(d, forward());
  if (z <= 0.0f) return std::nullopt;
  if (lens) {
    // OpenCV's frame: +y down, pixel centres at integers.
    const glm::dvec2 ideal(glm::dot(d, right()) / z, -glm::dot(d, up()) / z);
    return normalisedToPixel(*lens, distortNormalised(*lens, ideal));
  }
  const glm::dvec2 uv = pinholeUv(*this, d, z);
  return glm::dvec2((uv.x + 1.0) * 0.5 * width - 0.5, (1.0 - uv.y) * 0.5 * height - 0.5);
}

glm::ivec2 Camera::project(const glm::vec3& point) const {
  int x = -1, y = -1;
  if (lens) {
    const std::optional<glm::dvec2> px = imagePoint(point);  // centres at integers: round
    if (!px) return {-1, -1};
    x = static_cast<int>(std::floor(px->x + 0.5));
    y = static_cast<int>(std::floor(px->y + 0.5));
  } else {
    // The pixel edges at (u + 1) W / 2 exactly, as the G-buffer's raster.
    const glm::vec3 d = point - position_world;
    const float z = glm::dot(d, forward());
    if (z <= 0.0f) return {-1, -1};
    const glm::dvec2 uv = pinholeUv(*this, d, z);
    x = static_cast<int>(std::floor((uv.x + 1.0) * 0.5 * width));
    y = static_cast<int>(std::floor((1.0 - uv.y) * 0.5 * height));
  }
  if (x < 0 || y < 0 || x >= width || y >= height) return {-1, -1};
  return {x, y};
}

glm::mat4 Camera::view() const { return glm::lookAt(position_world, look_at_world, up_world); }

glm::mat4 Camera::projection(float near_m, float far_m) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  glm::mat4 p = glm::perspective(glm::radians(fov_y_deg), aspect, near_m, far_m);
  // Flip clip-space y so framebuffer row 0 holds the top of the image.
  return glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f)) * p;
}

}  // namespace tofsim::capture
