#pragma once
// Private to the optics library: a 2-D discrete Fourier transform of
// power-of-two sizes (iterative radix-2, in double), all the PSF's wide
// image kernels need. Written here rather than taken from FFTW: a kernel of
// a few hundred pixels on a sensor of a few hundred is far from where FFTW's
// planning pays, and tofsim keeps its Debian dependencies few.

#include <complex>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tofsim::optics {

class Fft2d {
 public:
  /// A transform of ny rows of nx values; both powers of two.
  Fft2d(int32_t nx, int32_t ny);
  int32_t nx() const { return nx_; }
  int32_t ny() const { return ny_; }
  /// In place on nx * ny values, row-major: X[k] = sum x[n] e^(-2 pi i k n / N).
  /// Rows from `rows` on must be zero (a zero-padded image): their 1-D
  /// transforms are skipped.
  void forward(std::complex<double>* data, int32_t rows) const;
  void forward(std::complex<double>* data) const { forward(data, ny_); }
  /// The inverse, divided by nx * ny: inverse(forward(x)) = x; only the
  /// first `rows` rows are completed (the others are left partial).
  void inverse(std::complex<double>* data, int32_t rows) const;
  void inverse(std::complex<double>* data) const { inverse(data, ny_); }

  /// The smallest power of two >= n.
  static int32_t powerOfTwoAtLeast(int32_t n);

 private:
  struct Line {
    explicit Line(int32_t n);
    /// In place on n contiguous values; the inverse without the 1 / n.
    void transform(std::complex<double>* data, bool inverse) const;
    /// The same along the other axis of n rows of `width` values: whole rows
    /// combined at each step (contiguous, vectorisable).
    void transformRows(std::complex<double>* data, int32_t width, bool inverse) const;
    int32_t n;
    std::vector<int32_t> reversed;            ///< bit-reversed index of each index
    std::vector<std::complex<double>> roots;  ///< e^(-2 pi i k / n), k < n / 2
  };
  int32_t nx_, ny_;
  Line alongX_, alongY_;
};

}  // namespace tofsim::optics
