#include "tofsim/capture/Lens.h"

#include <cmath>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::capture {

namespace {

// OpenCV's computeTiltProjectionMatrix (opencv2/calib3d/distortion_model.hpp):
// the sensor tilted by tau_x about x, then tau_y about y, projected back onto
// the z = 1 plane.
glm::dmat3 tiltProjection(double tauX, double tauY) {
  const double cX = std::cos(tauX), sX = std::sin(tauX);
  const double cY = std::cos(tauY), sY = std::sin(tauY);
  // glm is column-major: dmat3(col0, col1, col2).
  const glm::dmat3 rotX(glm::dvec3(1, 0, 0), glm::dvec3(0, cX, -sX), glm::dvec3(0, sX, cX));
  const glm::dmat3 rotY(glm::dvec3(cY, 0, sY), glm::dvec3(0, 1, 0), glm::dvec3(-sY, 0, cY));
  const glm::dmat3 rotXY = rotY * rotX;
  // OpenCV's matRotXY(r, c) is glm's rotXY[c][r] (column-major).
  const glm::dmat3 projZ(glm::dvec3(rotXY[2][2], 0, 0), glm::dvec3(0, rotXY[2][2], 0),
                         glm::dvec3(-rotXY[2][0], -rotXY[2][1], 1));
  return projZ * rotXY;
}

// Newton's method: iterations, and the residual (normalised units) it stops at.
constexpr int kMaxNewtonSteps = 50;
constexpr double kNewtonTolerance = 1e-15;

}  // namespace

bool Lens::distorted() const {
  for (const double d : distortion) {
    if (d != 0.0) return true;
  }
  return false;
}

glm::dvec2 distortNormalised(const Lens& lens, glm::dvec2 p) {
  const auto& d = lens.distortion;
  const double k1 = d[0], k2 = d[1], p1 = d[2], p2 = d[3], k3 = d[4], k4 = d[5], k5 = d[6],
               k6 = d[7], s1 = d[8], s2 = d[9], s3 = d[10], s4 = d[11];
  const double r2 = p.x * p.x + p.y * p.y, r4 = r2 * r2, r6 = r4 * r2;
  const double radial = (1.0 + k1 * r2 + k2 * r4 + k3 * r6) / (1.0 + k4 * r2 + k5 * r4 + k6 * r6);
  const double a1 = 2.0 * p.x * p.y;
  glm::dvec2 q(p.x * radial + p1 * a1 + p2 * (r2 + 2.0 * p.x * p.x) + s1 * r2 + s2 * r4,
               p.y * radial + p1 * (r2 + 2.0 * p.y * p.y) + p2 * a1 + s3 * r2 + s4 * r4);
  if (d[12] != 0.0 || d[13] != 0.0) {
    const glm::dvec3 t = tiltProjection(d[12], d[13]) * glm::dvec3(q, 1.0);
    q = glm::dvec2(t.x, t.y) / t.z;
  }
  return q;
}

glm::dmat2 distortionJacobian(const Lens& lens, glm::dvec2 p) {
  // Central differences: the model is a smooth rational function and the
  // footprint and Newton's steps need ~1e-9 relative, which h = 1e-6 gives.
  constexpr double h = 1e-6;
  const glm::dvec2 dx =
      (distortNormalised(lens, p + glm::dvec2(h, 0)) - distortNormalised(lens, p - glm::dvec2(h, 0))) /
      (2.0 * h);
  const glm::dvec2 dy =
      (distortNormalised(lens, p + glm::dvec2(0, h)) - distortNormalised(lens, p - glm::dvec2(0, h))) /
      (2.0 * h);
  return glm::dmat2(dx, dy);
}

bool undistortNormalised(const Lens& lens, glm::dvec2 distorted, glm::dvec2& ideal) {
  glm::dvec2 p = distorted;
  // A root on a folded branch (beyond the fold, where the Jacobian's
  // determinant is negative, or mirrored through the centre) is no ray of
  // this pixel; checkLensInvertible tests the whole image once.
  const auto accept = [&](double tolerance) {
    const glm::dvec2 residual = distortNormalised(lens, p) - distorted;
    if (!(std::fabs(residual.x) < tolerance && std::fabs(residual.y) < tolerance)) return false;
    if (!(glm::determinant(distortionJacobian(lens, p)) > 0.0)) return false;
    if (glm::dot(p, distorted) < 0.0) return false;
    ideal = p;
    return true;
  };
  for (int step = 0; step < kMaxNewtonSteps; ++step) {
    const glm::dvec2 residual = distortNormalised(lens, p) - distorted;
    if (std::fabs(residual.x) < kNewtonTolerance && std::fabs(residual.y) < kNewtonTolerance) {
      return accept(kNewtonTolerance);
    }
    const glm::dmat2 J = distortionJacobian(lens, p);
    if (!(std::fabs(glm::determinant(J)) > 1e-12)) return false;  // at a fold
    p -= glm::inverse(J) * residual;
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  }
  // Rounding may keep the residual a few ulps above the tolerance: accept it
  // at the level of double precision.
  return accept(1e-13);
}

void checkLensInvertible(const Lens& lens, int32_t width, int32_t height) {
  const auto fail = [&](int32_t x, int32_t y, const std::string& why) {
    throw InputError("the lens distortion is not invertible at pixel (" + std::to_string(x) +
                     ", " + std::to_string(y) + ") of the " + std::to_string(width) + " x " +
                     std::to_string(height) + " image: " + why +
                     " (coefficients that fold the image inside the field of view)");
  };
  // Every pixel's ray (PixelRays inverts the distortion at each pixel and
  // relies on this check: a fold between the grid's pixels was found by
  // fuzz_camera_files), and for the border pixels and an 8 x 8 grid the
  // Jacobian along the ideal segment from the centre out to the ray: a fold
  // anywhere inside lies on one such segment when the distortion is close
  // to radial. One pass, row by row.
  constexpr int kSteps = 32;
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) {
      glm::dvec2 ideal;
      if (!undistortNormalised(lens, pixelToNormalised(lens, {double(x), double(y)}), ideal)) {
        fail(x, y, "no ray has this distorted position");
      }
      const bool border = x == 0 || y == 0 || x == width - 1 || y == height - 1;
      if (!border && (x % 8 != 0 || y % 8 != 0)) continue;
      for (int k = 1; k <= kSteps; ++k) {
        const glm::dvec2 p = ideal * (static_cast<double>(k) / kSteps);
        if (!(glm::determinant(distortionJacobian(lens, p)) > 0.0)) {
          fail(x, y, "the distortion folds between the centre and this pixel's ray");
        }
      }
    }
  }
}

glm::dvec2 pixelToNormalised(const Lens& lens, glm::dvec2 pixel) {
  return {(pixel.x - lens.cx) / lens.fx, (pixel.y - lens.cy) / lens.fy};
}

glm::dvec2 normalisedToPixel(const Lens& lens, glm::dvec2 n) {
  return {lens.fx * n.x + lens.cx, lens.fy * n.y + lens.cy};
}

}  // namespace tofsim::capture
