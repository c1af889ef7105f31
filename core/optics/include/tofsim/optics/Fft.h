#pragma once
// A 1-D discrete Fourier transform of a power-of-two count of values, for
// code outside the optics library that evaluates a series on an even grid
// (a measured CW-ToF waveform's maximum: sensors/src/CwTofWaveform.cpp).
// The same radix-2 transform as the PSF's 2-D one (Fft2d), one row of it.

#include <complex>
#include <vector>

namespace tofsim::optics {

/// In place: X[k] = sum_n x[n] e^(-2 pi i k n / N); data.size() is a power of
/// two (checked).
void fourierTransform(std::vector<std::complex<double>>& data);

/// The smallest power of two >= n (n <= 2^30).
int powerOfTwoAtLeast(int n);

}  // namespace tofsim::optics
