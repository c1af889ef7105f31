#pragma once
// A lens's point spread function on the pixel grid: the share K(dx, dy) of a
// pixel's light that the lens puts dx pixels to the right and dy pixels down
// of it. Sum K = 1: the lens moves light, it makes none and loses none
// (what falls off the sensor is the convolution's business, PsfConvolution.h).
//
// Scattered light keeps its delay (the paths inside the lens are negligible
// against the scene's), so the same K acts on every time bin of a transient,
// and by linearity on a CW-ToF camera's raw correlation images.
//
// The kernel is a weighted sum of terms, each normalised: a separable term
// (a 1-D profile along x times one along y: the Gaussians, convolved in two
// 1-D passes) or an image term (any 2-D profile: an exponential halo, a
// measured kernel). The parametric form is the usual stray-light model
// K = (1 - s) core + s halo [detector-models.md section 3].

#include <cstdint>
#include <string>
#include <vector>

namespace tofsim::optics {

/// One normalised part of a kernel, centred on pixel (0, 0).
struct PsfTerm {
  double weight = 1.0;  ///< its share of the light, in (0, 1]
  /// Separable: odd-length profiles along x and along y, each summing to 1,
  /// centre at index size / 2. Empty for an image term.
  std::vector<double> alongX, alongY;
  /// Image: (2 radiusY + 1) x (2 radiusX + 1) values, row-major (dy = -radiusY
  /// first), summing to 1. Empty for a separable term.
  std::vector<double> image;
  int32_t radiusX = 0, radiusY = 0;

  bool separable() const { return image.empty(); }
  /// The term's value at offset (dx, dy); 0 outside its support.
  double at(int32_t dx, int32_t dy) const;
};

/// The halo's radial profile: a Gaussian (sigma = the radius) or an
/// exponential exp(-r / radius), the long tail measured stray light has.
enum class HaloProfile { Gaussian, Exponential };
/// "gaussian", "exponential".
const char* haloProfileName(HaloProfile profile);

/// The parametric kernel (1 - s) core + s halo.
struct PsfParams {
  /// The core's Gaussian sigma (pixel, >= 0), integrated over each pixel;
  /// 0: a delta, the pixel keeps its own light.
  double core_sigma_px = 0.0;
  /// s: the halo's share of the light, in [0, 1).
  double halo_weight = 0.0;
  HaloProfile halo_profile = HaloProfile::Gaussian;
  /// The halo's sigma (Gaussian) or decay length (exponential), pixel, > 0
  /// when halo_weight > 0.
  double halo_radius_px = 0.0;
};

/// Where the profiles are cut (in sigmas or decay lengths): the light beyond
/// is below 1e-4 of the term (a Gaussian beyond 5 sigma: 6e-7 per axis; an
/// exponential beyond 12 decay lengths: 13 e^-12 = 8e-5), and each term is
/// normalised over what is kept.
inline constexpr double kGaussianCutSigmas = 5.0;
inline constexpr double kExponentialCutRadii = 12.0;

/// parametric's crop_px default: the whole cut support is kept.
inline constexpr int32_t kNoCrop = 1 << 30;

class PsfKernel {
 public:
  /// The identity (a delta): every pixel keeps its light.
  PsfKernel();
  /// (1 - s) core + s halo. Throws InputError for a sigma < 0, s outside
  /// [0, 1), a halo radius <= 0 with s > 0 or any value not finite.
  /// Each term is normalised over its whole cut support, then kept only to
  /// offsets <= crop_px: light moved further leaves any image of at most
  /// crop_px + 1 pixels a side, where it is lost anyway, so an image that
  /// small sees the same result from a far smaller kernel (the sum of the
  /// kept values is then below 1 by what is lost).
  static PsfKernel parametric(const PsfParams& params, int32_t crop_px = kNoCrop);
  /// A measured kernel: height x width values row-major (odd sizes, finite,
  /// >= 0, a positive sum), normalised to sum 1. Throws InputError naming the
  /// first bad value's (y, x) otherwise.
  static PsfKernel fromImage(const std::vector<double>& values, int32_t height, int32_t width);

  const std::vector<PsfTerm>& terms() const { return terms_; }
  /// The largest offsets with light (over the terms).
  int32_t radiusX() const;
  int32_t radiusY() const;
  /// K(dx, dy): the sum of the weighted terms.
  double at(int32_t dx, int32_t dy) const;
  /// The whole kernel as one image, (2 radiusY() + 1) x (2 radiusX() + 1)
  /// row-major: the direct convolution's (and the tests') view of it.
  std::vector<double> image() const;
  /// Whether it is the identity (convolving is then a no-op).
  bool identity() const;

 private:
  explicit PsfKernel(std::vector<PsfTerm> terms);
  std::vector<PsfTerm> terms_;
};

/// A Gaussian of sigma (pixel) integrated over each pixel, cut at
/// kGaussianCutSigmas and normalised, then kept to |offset| <= crop_px;
/// sigma 0: {1}.
std::vector<double> gaussianProfile(double sigma_px, int32_t crop_px = kNoCrop);

}  // namespace tofsim::optics
