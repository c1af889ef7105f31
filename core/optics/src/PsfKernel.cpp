#include "tofsim/optics/PsfKernel.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim::optics {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

void normalise(std::vector<double>& v) {
  const double total = sum(v);
  for (double& x : v) x /= total;
}

// exp(-r / radius) at the pixel centres of the disc r <= 12 radius,
// normalised over the whole disc, kept to |dx|, |dy| <= crop_px.
PsfTerm exponentialTerm(double weight, double radius_px, int32_t crop_px) {
  const double cut = kExponentialCutRadii * radius_px;
  const auto full = static_cast<int32_t>(std::ceil(cut));
  const auto value = [&](int32_t dx, int32_t dy) {
    const double r = std::sqrt(double(dx) * dx + double(dy) * dy);
    return r <= cut ? std::exp(-r / radius_px) : 0.0;
  };
  double total = 0.0;  // over the whole disc, stored or not
  for (int32_t dy = -full; dy <= full; ++dy) {
    for (int32_t dx = -full; dx <= full; ++dx) total += value(dx, dy);
  }
  PsfTerm t;
  t.weight = weight;
  t.radiusX = t.radiusY = std::min(full, crop_px);
  const int32_t r = t.radiusX;
  t.image.reserve(static_cast<std::size_t>(2 * r + 1) * (2 * r + 1));
  for (int32_t dy = -r; dy <= r; ++dy) {
    for (int32_t dx = -r; dx <= r; ++dx) t.image.push_back(value(dx, dy) / total);
  }
  return t;
}

PsfTerm gaussianTerm(double weight, double sigma_px, int32_t crop_px) {
  PsfTerm t;
  t.weight = weight;
  t.alongX = gaussianProfile(sigma_px, crop_px);
  t.alongY = t.alongX;
  return t;
}

void requireFinite(double v, const char* name) {
  if (!std::isfinite(v))
    throw InputError(std::string(name) + " must be finite (got " + number(v) + ")");
}

}  // namespace

const char* haloProfileName(HaloProfile profile) {
  return profile == HaloProfile::Exponential ? "exponential" : "gaussian";
}

double PsfTerm::at(int32_t dx, int32_t dy) const {
  if (separable()) {
    const auto rx = static_cast<int32_t>(alongX.size() / 2);
    const auto ry = static_cast<int32_t>(alongY.size() / 2);
    if (std::abs(dx) > rx || std::abs(dy) > ry) return 0.0;
    return alongX[dx + rx] * alongY[dy + ry];
  }
  if (std::abs(dx) > radiusX || std::abs(dy) > radiusY) return 0.0;
  return image[static_cast<std::size_t>(dy + radiusY) * (2 * radiusX + 1) + (dx + radiusX)];
}

std::vector<double> gaussianProfile(double sigma_px, int32_t crop_px) {
  TOFSIM_CHECK(sigma_px >= 0.0 && crop_px >= 0);
  if (sigma_px == 0.0) return {1.0};
  const auto full = static_cast<int32_t>(std::ceil(kGaussianCutSigmas * sigma_px));
  // The mass of pixel i: Phi((i + 1/2) / sigma) - Phi((i - 1/2) / sigma),
  // written with erfc on the tail side so that far pixels keep their digits.
  const double k = 1.0 / (sigma_px * std::sqrt(2.0));
  std::vector<double> half(full + 1);  // i = 0 .. full
  half[0] = std::erf(0.5 * k);
  for (int32_t i = 1; i <= full; ++i) {
    half[i] = 0.5 * (std::erfc((i - 0.5) * k) - std::erfc((i + 0.5) * k));
  }
  double total = half[0];
  for (int32_t i = 1; i <= full; ++i) total += 2.0 * half[i];
  const int32_t kept = std::min(full, crop_px);
  std::vector<double> p(2 * kept + 1);
  for (int32_t i = -kept; i <= kept; ++i) p[i + kept] = half[std::abs(i)] / total;
  return p;
}

PsfKernel::PsfKernel() : PsfKernel(std::vector<PsfTerm>{gaussianTerm(1.0, 0.0, 0)}) {}

PsfKernel::PsfKernel(std::vector<PsfTerm> terms) : terms_(std::move(terms)) {}

PsfKernel PsfKernel::parametric(const PsfParams& params, int32_t crop_px) {
  TOFSIM_CHECK(crop_px >= 0);
  requireFinite(params.core_sigma_px, "the core's sigma");
  requireFinite(params.halo_weight, "the halo's weight");
  requireFinite(params.halo_radius_px, "the halo's radius");
  if (params.core_sigma_px < 0.0) {
    throw InputError("the core's sigma must be >= 0 pixels (got " + number(params.core_sigma_px) +
                     ")");
  }
  if (!(params.halo_weight >= 0.0 && params.halo_weight < 1.0)) {
    throw InputError("the halo's weight must be in [0, 1) (got " + number(params.halo_weight) +
                     ")");
  }
  const double s = params.halo_weight;
  std::vector<PsfTerm> terms{gaussianTerm(1.0 - s, params.core_sigma_px, crop_px)};
  if (s > 0.0) {
    if (!(params.halo_radius_px > 0.0)) {
      throw InputError("the halo's radius must be > 0 pixels (got " +
                       number(params.halo_radius_px) + ")");
    }
    terms.push_back(params.halo_profile == HaloProfile::Gaussian
                        ? gaussianTerm(s, params.halo_radius_px, crop_px)
                        : exponentialTerm(s, params.halo_radius_px, crop_px));
  }
  return PsfKernel(std::move(terms));
}

PsfKernel PsfKernel::fromImage(const std::vector<double>& values, int32_t height, int32_t width) {
  TOFSIM_CHECK_EQ(values.size(), static_cast<std::size_t>(height) * width);
  if (height % 2 == 0 || width % 2 == 0) {
    throw InputError("a PSF kernel needs odd sizes, its centre on a pixel (got " +
                     std::to_string(height) + " x " + std::to_string(width) + ", H x W)");
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]) || values[i] < 0.0) {
      throw InputError("PSF value " + number(values[i]) + " at (y, x) = (" +
                       std::to_string(i / width) + ", " + std::to_string(i % width) + ") is " +
                       (values[i] < 0.0 ? "negative" : "not finite"));
    }
  }
  if (!(sum(values) > 0.0)) throw InputError("a PSF kernel's values must not all be 0");
  PsfTerm t;
  t.image = values;
  normalise(t.image);
  t.radiusX = width / 2;
  t.radiusY = height / 2;
  return PsfKernel({std::move(t)});
}

int32_t PsfKernel::radiusX() const {
  int32_t r = 0;
  for (const PsfTerm& t : terms_) {
    r = std::max(r, t.separable() ? static_cast<int32_t>(t.alongX.size() / 2) : t.radiusX);
  }
  return r;
}

int32_t PsfKernel::radiusY() const {
  int32_t r = 0;
  for (const PsfTerm& t : terms_) {
    r = std::max(r, t.separable() ? static_cast<int32_t>(t.alongY.size() / 2) : t.radiusY);
  }
  return r;
}

double PsfKernel::at(int32_t dx, int32_t dy) const {
  double k = 0.0;
  for (const PsfTerm& t : terms_) k += t.weight * t.at(dx, dy);
  return k;
}

std::vector<double> PsfKernel::image() const {
  const int32_t rx = radiusX(), ry = radiusY();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(2 * rx + 1) * (2 * ry + 1));
  for (int32_t dy = -ry; dy <= ry; ++dy) {
    for (int32_t dx = -rx; dx <= rx; ++dx) out.push_back(at(dx, dy));
  }
  return out;
}

bool PsfKernel::identity() const { return radiusX() == 0 && radiusY() == 0 && at(0, 0) == 1.0; }

}  // namespace tofsim::optics
