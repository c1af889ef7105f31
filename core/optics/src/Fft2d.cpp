#include "Fft2d.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim::optics {

namespace {
bool powerOfTwo(int32_t n) { return n > 0 && (n & (n - 1)) == 0; }
}  // namespace

int32_t Fft2d::powerOfTwoAtLeast(int32_t n) {
  int32_t p = 1;
  while (p < n) p *= 2;
  return p;
}

Fft2d::Line::Line(int32_t size) : n(size), reversed(size), roots(size / 2) {
  TOFSIM_CHECK(powerOfTwo(size));
  int32_t bits = 0;
  while ((1 << bits) < n) ++bits;
  for (int32_t i = 0; i < n; ++i) {
    int32_t r = 0;
    for (int32_t b = 0; b < bits; ++b) r |= ((i >> b) & 1) << (bits - 1 - b);
    reversed[i] = r;
  }
  // Each root from its own angle (not by repeated multiplication), so every
  // twiddle is correct to the last bits.
  for (int32_t k = 0; k < n / 2; ++k) {
    roots[k] = std::polar(1.0, -2.0 * std::numbers::pi * k / n);
  }
}

void Fft2d::Line::transform(std::complex<double>* data, bool inverse) const {
  for (int32_t i = 0; i < n; ++i) {
    if (i < reversed[i]) std::swap(data[i], data[reversed[i]]);
  }
  for (int32_t len = 2; len <= n; len *= 2) {
    const int32_t half = len / 2, step = n / len;
    for (int32_t start = 0; start < n; start += len) {
      for (int32_t j = 0; j < half; ++j) {
        const std::complex<double> w = inverse ? std::conj(roots[j * step]) : roots[j * step];
        const std::complex<double> a = data[start + j];
        const std::complex<double> b = data[start + j + half] * w;
        data[start + j] = a + b;
        data[start + j + half] = a - b;
      }
    }
  }
}

void Fft2d::Line::transformRows(std::complex<double>* data, int32_t width, bool inverse) const {
  const auto row = [&](int32_t i) { return data + static_cast<std::size_t>(i) * width; };
  for (int32_t i = 0; i < n; ++i) {
    if (i < reversed[i]) std::swap_ranges(row(i), row(i) + width, row(reversed[i]));
  }
  for (int32_t len = 2; len <= n; len *= 2) {
    const int32_t half = len / 2, step = n / len;
    for (int32_t start = 0; start < n; start += len) {
      for (int32_t j = 0; j < half; ++j) {
        const std::complex<double> w = inverse ? std::conj(roots[j * step]) : roots[j * step];
        std::complex<double>* a = row(start + j);
        std::complex<double>* b = row(start + j + half);
        for (int32_t x = 0; x < width; ++x) {
          const std::complex<double> bw = b[x] * w;
          b[x] = a[x] - bw;
          a[x] += bw;
        }
      }
    }
  }
}

Fft2d::Fft2d(int32_t nx, int32_t ny) : nx_(nx), ny_(ny), alongX_(nx), alongY_(ny) {}

void Fft2d::forward(std::complex<double>* data, int32_t rows) const {
  TOFSIM_CHECK(rows >= 0 && rows <= ny_);
  for (int32_t y = 0; y < rows; ++y) alongX_.transform(data + std::size_t(y) * nx_, false);
  alongY_.transformRows(data, nx_, false);
}

void Fft2d::inverse(std::complex<double>* data, int32_t rows) const {
  TOFSIM_CHECK(rows >= 0 && rows <= ny_);
  alongY_.transformRows(data, nx_, true);
  const double scale = 1.0 / (double(nx_) * ny_);
  for (int32_t y = 0; y < rows; ++y) {
    std::complex<double>* r = data + std::size_t(y) * nx_;
    alongX_.transform(r, true);
    for (int32_t x = 0; x < nx_; ++x) r[x] *= scale;
  }
}

}  // namespace tofsim::optics
