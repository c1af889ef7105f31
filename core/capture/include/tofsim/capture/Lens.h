#pragma once
// A calibrated camera's lens as OpenCV describes it: the camera matrix (fx,
// fy, cx, cy) and the distortion coefficients in OpenCV's order (k1, k2, p1,
// p2[, k3[, k4, k5, k6[, s1, s2, s3, s4[, tau_x, tau_y]]]]), so the output of
// cv::calibrateCamera (or an Azure Kinect calibration) plugs in unchanged.
// Pixel coordinates are OpenCV's: pixel (x, y)'s centre at (x, y), +y down.
// Normalised coordinates are a ray (x, y, 1) in OpenCV's camera frame (+x
// right, +y down, +z forward). Everything is double: undistortion must invert
// distortion to ~1e-12 for the rays to be exact.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace tofsim::capture {

struct Lens {
  double fx = 1.0, fy = 1.0;  ///< focal lengths, pixels
  double cx = 0.0, cy = 0.0;  ///< principal point, pixels (OpenCV's: pixel centres at integers)
  /// k1 k2 p1 p2 k3 k4 k5 k6 s1 s2 s3 s4 tau_x tau_y; the ones a calibration
  /// does not give are 0 (OpenCV's convention for 4, 5, 8, 12 coefficients).
  std::array<double, 14> distortion{};

  bool distorted() const;
};

/// Normalised ideal coordinates -> normalised distorted ones, OpenCV's
/// model (cv::projectPoints without the camera matrix), tilt included.
glm::dvec2 distortNormalised(const Lens& lens, glm::dvec2 ideal);

/// The Jacobian d(distorted) / d(ideal) at `ideal` (columns: d/dx, d/dy).
glm::dmat2 distortionJacobian(const Lens& lens, glm::dvec2 ideal);

/// The ideal normalised coordinates whose distortion is `distorted`, by
/// Newton's method from the distorted point; nothing when it does not
/// converge (outside the region where the distortion is invertible).
bool undistortNormalised(const Lens& lens, glm::dvec2 distorted, glm::dvec2& ideal);

/// Throws InputError naming the first pixel of a width x height image
/// where the lens is not invertible: no undistorted ray, or a fold (the
/// Jacobian's determinant <= 0) between the image centre's ray and a border
/// pixel's, where two rays would meet in one pixel.
void checkLensInvertible(const Lens& lens, int32_t width, int32_t height);

/// Pixel <-> distorted normalised coordinates through the camera matrix.
glm::dvec2 pixelToNormalised(const Lens& lens, glm::dvec2 pixel);
glm::dvec2 normalisedToPixel(const Lens& lens, glm::dvec2 normalised);

}  // namespace tofsim::capture
