#include "tofsim/optics/PsfConvolution.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <optional>
#include <vector>

#include "Fft2d.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::optics {

namespace {

using Complex = std::complex<double>;

// A term cut to the offsets that can reach from one pixel of the image to
// another (|dx| < W, |dy| < H): the rest only throws light off the sensor.
struct Term {
  double weight = 1.0;
  bool separable = true;
  int32_t rx = 0, ry = 0;
  std::vector<double> alongX, alongY;  ///< separable: 2 rx + 1 and 2 ry + 1 values
  std::vector<double> image;           ///< image: (2 ry + 1) x (2 rx + 1)
  std::optional<Fft2d> fft;            ///< image terms summed by FFT
  std::vector<Complex> spectrum;       ///< the kernel's transform on fft's grid

  double at(int32_t dx, int32_t dy) const {
    return image[static_cast<std::size_t>(dy + ry) * (2 * rx + 1) + (dx + rx)];
  }
};

std::vector<double> middle(const std::vector<double>& v, int32_t radius) {
  const auto centre = static_cast<int32_t>(v.size() / 2);
  return {v.begin() + (centre - radius), v.begin() + (centre + radius + 1)};
}

Term imageTerm(double weight, int32_t rx, int32_t ry, const std::vector<double>& image,
               int32_t width, int32_t height) {
  Term t;
  t.weight = weight;
  t.separable = false;
  t.rx = std::min(rx, width - 1);
  t.ry = std::min(ry, height - 1);
  t.image.reserve(static_cast<std::size_t>(2 * t.rx + 1) * (2 * t.ry + 1));
  for (int32_t dy = -t.ry; dy <= t.ry; ++dy) {
    for (int32_t dx = -t.rx; dx <= t.rx; ++dx) {
      t.image.push_back(image[static_cast<std::size_t>(dy + ry) * (2 * rx + 1) + (dx + rx)]);
    }
  }
  return t;
}

// Multiply-adds of the direct sum against the FFT's estimated operations
// (a complex butterfly ~ 5 real operations per value and level; forward and
// inverse; two planes share a transform). Dense planes assumed.
bool fftCheaper(const Term& t, int32_t width, int32_t height) {
  const double direct = double(width) * height * (2 * t.rx + 1) * (2 * t.ry + 1);
  const double px = Fft2d::powerOfTwoAtLeast(width + t.rx);
  const double py = Fft2d::powerOfTwoAtLeast(height + t.ry);
  const double fft = 5.0 * px * py * std::log2(px * py);  // per plane: 2 transforms / 2 planes
  return fft < direct;
}

void prepareFft(Term& t, int32_t width, int32_t height) {
  // Circular convolution on P >= W + r values wraps nothing onto the image.
  t.fft.emplace(Fft2d::powerOfTwoAtLeast(width + t.rx), Fft2d::powerOfTwoAtLeast(height + t.ry));
  const int32_t px = t.fft->nx(), py = t.fft->ny();
  t.spectrum.assign(static_cast<std::size_t>(px) * py, Complex(0.0));
  for (int32_t dy = -t.ry; dy <= t.ry; ++dy) {
    for (int32_t dx = -t.rx; dx <= t.rx; ++dx) {
      const int32_t x = (dx + px) % px, y = (dy + py) % py;
      t.spectrum[static_cast<std::size_t>(y) * px + x] = t.at(dx, dy);
    }
  }
  t.fft->forward(t.spectrum.data());
}

class PlaneConvolver {
 public:
  PlaneConvolver(const PsfKernel& kernel, int32_t width, int32_t height, PsfMethod method)
      : width_(width), height_(height) {
    if (method != PsfMethod::Auto) {
      terms_.push_back(
          imageTerm(1.0, kernel.radiusX(), kernel.radiusY(), kernel.image(), width, height));
      if (method == PsfMethod::Fft) prepareFft(terms_.back(), width, height);
      return;
    }
    for (const PsfTerm& k : kernel.terms()) {
      if (k.separable()) {
        Term t;
        t.weight = k.weight;
        t.rx = std::min(static_cast<int32_t>(k.alongX.size() / 2), width - 1);
        t.ry = std::min(static_cast<int32_t>(k.alongY.size() / 2), height - 1);
        t.alongX = middle(k.alongX, t.rx);
        t.alongY = middle(k.alongY, t.ry);
        terms_.push_back(std::move(t));
        continue;
      }
      terms_.push_back(imageTerm(k.weight, k.radiusX, k.radiusY, k.image, width, height));
      if (fftCheaper(terms_.back(), width, height)) prepareFft(terms_.back(), width, height);
    }
  }

  /// n (1 or 2) planes of W x H doubles: out[i] = K * in[i].
  void convolve(const double* const* in, double* const* out, int n) const {
    const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
    std::vector<double> part(pixels), scratch(pixels);
    for (int i = 0; i < n; ++i) std::fill(out[i], out[i] + pixels, 0.0);
    for (const Term& t : terms_) {
      if (t.fft) {
        fftPair(t, in, out, n);
        continue;
      }
      for (int i = 0; i < n; ++i) {
        if (t.separable) {
          separable(t, in[i], scratch.data(), part.data());
        } else {
          direct(t, in[i], part.data());
        }
        for (std::size_t p = 0; p < pixels; ++p) out[i][p] += t.weight * part[p];
      }
    }
  }

 private:
  // Along x into `row`, then along y into `out`.
  void separable(const Term& t, const double* in, double* rows, double* out) const {
    const int32_t w = width_, h = height_;
    for (int32_t y = 0; y < h; ++y) {
      const double* src = in + static_cast<std::size_t>(y) * w;
      double* dst = rows + static_cast<std::size_t>(y) * w;
      for (int32_t x = 0; x < w; ++x) {
        double s = 0.0;
        const int32_t lo = std::max(-t.rx, x - (w - 1)), hi = std::min(t.rx, x);
        for (int32_t d = lo; d <= hi; ++d) s += t.alongX[d + t.rx] * src[x - d];
        dst[x] = s;
      }
    }
    std::fill(out, out + static_cast<std::size_t>(w) * h, 0.0);
    for (int32_t y = 0; y < h; ++y) {
      const int32_t lo = std::max(-t.ry, y - (h - 1)), hi = std::min(t.ry, y);
      double* dst = out + static_cast<std::size_t>(y) * w;
      for (int32_t d = lo; d <= hi; ++d) {
        const double k = t.alongY[d + t.ry];
        const double* src = rows + static_cast<std::size_t>(y - d) * w;
        for (int32_t x = 0; x < w; ++x) dst[x] += k * src[x];
      }
    }
  }

  // Each lit pixel's light spread over its kernel, clipped to the image.
  void direct(const Term& t, const double* in, double* out) const {
    const int32_t w = width_, h = height_;
    std::fill(out, out + static_cast<std::size_t>(w) * h, 0.0);
    for (int32_t y = 0; y < h; ++y) {
      for (int32_t x = 0; x < w; ++x) {
        const double v = in[static_cast<std::size_t>(y) * w + x];
        if (v == 0.0) continue;
        const int32_t dyLo = std::max(-t.ry, -y), dyHi = std::min(t.ry, h - 1 - y);
        const int32_t dxLo = std::max(-t.rx, -x), dxHi = std::min(t.rx, w - 1 - x);
        for (int32_t dy = dyLo; dy <= dyHi; ++dy) {
          const double* k = &t.image[static_cast<std::size_t>(dy + t.ry) * (2 * t.rx + 1) + t.rx];
          double* dst = out + static_cast<std::size_t>(y + dy) * w + x;
          for (int32_t dx = dxLo; dx <= dxHi; ++dx) dst[dx] += k[dx] * v;
        }
      }
    }
  }

  // Two real planes as one complex one: the kernel is real, so the real and
  // the imaginary part of the result are the two convolutions.
  void fftPair(const Term& t, const double* const* in, double* const* out, int n) const {
    const int32_t px = t.fft->nx(), py = t.fft->ny();
    std::vector<Complex> grid(static_cast<std::size_t>(px) * py, Complex(0.0));
    for (int32_t y = 0; y < height_; ++y) {
      for (int32_t x = 0; x < width_; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
        grid[static_cast<std::size_t>(y) * px + x] = Complex(in[0][i], n > 1 ? in[1][i] : 0.0);
      }
    }
    t.fft->forward(grid.data(), height_);  // the padding rows are zero
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] *= t.spectrum[i];
    t.fft->inverse(grid.data(), height_);  // only the image's rows are read
    for (int32_t y = 0; y < height_; ++y) {
      for (int32_t x = 0; x < width_; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
        const Complex v = grid[static_cast<std::size_t>(y) * px + x];
        out[0][i] += t.weight * v.real();
        if (n > 1) out[1][i] += t.weight * v.imag();
      }
    }
  }

  int32_t width_, height_;
  std::vector<Term> terms_;
};

// Lit planes per task (even: the FFT's pairs stay whole).
constexpr std::size_t kPlanesPerTask = 16;

template <class T>
void applyPsfTo(const PsfKernel& kernel, T* values, std::size_t planes, const PlaneLayout& layout,
                const PsfOptions& options) {
  TOFSIM_CHECK(layout.width > 0 && layout.height > 0);
  if (planes == 0 || (kernel.identity() && options.method == PsfMethod::Auto)) return;
  const std::size_t pixels = static_cast<std::size_t>(layout.width) * layout.height;
  const auto at = [&](std::size_t plane, std::size_t pixel) -> T& {
    return values[plane * layout.planeStride + pixel * layout.pixelStride];
  };
  // The lit planes, found in one pass in the pixels' order (a transient's
  // memory order); the dark ones stay 0.
  std::vector<char> lit(planes, 0);
  for (std::size_t p = 0; p < pixels; ++p) {
    for (std::size_t j = 0; j < planes; ++j) lit[j] |= at(j, p) != T(0);
  }
  std::vector<std::size_t> litPlanes;
  for (std::size_t j = 0; j < planes; ++j) {
    if (lit[j]) litPlanes.push_back(j);
  }
  const PlaneConvolver convolver(kernel, layout.width, layout.height, options.method);
  // Fixed blocks of lit planes, each task one block: the tasks, and so the
  // bytes, do not depend on the thread count. A block is gathered and
  // written back in one pass over the pixels, which reads a transient's
  // neighbouring bins together rather than one strided plane at a time;
  // within it the planes go in pairs (the FFT's two planes per transform).
  const std::size_t blocks = (litPlanes.size() + kPlanesPerTask - 1) / kPlanesPerTask;
  parallelFor(blocks, resolveThreads(options.threads), [&](std::size_t block) {
    const std::size_t first = block * kPlanesPerTask;
    const std::size_t n = std::min(kPlanesPerTask, litPlanes.size() - first);
    std::vector<double> in(n * pixels), out(n * pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
      for (std::size_t i = 0; i < n; ++i) in[i * pixels + p] = double(at(litPlanes[first + i], p));
    }
    for (std::size_t i = 0; i < n; i += 2) {
      const int pair = i + 1 < n ? 2 : 1;
      const double* inputs[2] = {&in[i * pixels], pair > 1 ? &in[(i + 1) * pixels] : nullptr};
      double* outputs[2] = {&out[i * pixels], pair > 1 ? &out[(i + 1) * pixels] : nullptr};
      convolver.convolve(inputs, outputs, pair);
    }
    for (std::size_t p = 0; p < pixels; ++p) {
      for (std::size_t i = 0; i < n; ++i) at(litPlanes[first + i], p) = T(out[i * pixels + p]);
    }
  });
}

}  // namespace

void applyPsf(const PsfKernel& kernel, float* values, std::size_t planes, const PlaneLayout& layout,
              const PsfOptions& options) {
  applyPsfTo(kernel, values, planes, layout, options);
}

void applyPsf(const PsfKernel& kernel, double* values, std::size_t planes,
              const PlaneLayout& layout, const PsfOptions& options) {
  applyPsfTo(kernel, values, planes, layout, options);
}

void applyPsf(const PsfKernel& kernel, float* planes, int32_t count, int32_t height,
              int32_t width) {
  const PlaneLayout layout{width, height, 1, static_cast<std::size_t>(width) * height};
  applyPsf(kernel, planes, static_cast<std::size_t>(count), layout);
}

void applyPsf(const PsfKernel& kernel, double* planes, int32_t count, int32_t height,
              int32_t width) {
  const PlaneLayout layout{width, height, 1, static_cast<std::size_t>(width) * height};
  applyPsf(kernel, planes, static_cast<std::size_t>(count), layout);
}

}  // namespace tofsim::optics
