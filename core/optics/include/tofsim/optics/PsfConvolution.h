#pragma once
// The lens's PSF applied to image planes: out(x, y) = sum over (dx, dy) of
// K(dx, dy) in(x - dx, y - dy), each plane on its own (a time bin and colour
// channel of a transient, or one CW-ToF raw correlation image).
//
// At the border the light the kernel throws off the sensor is lost, as in a
// camera: the image is zero outside, and nothing is renormalised. A plane's
// sum is therefore kept exactly (to rounding: 1e-15 relative in double) when
// every lit pixel's kernel support stays in the image, and falls by what
// leaves it otherwise. (Light from outside the field of view that a real lens
// scatters in is not simulated: the renderer never sees that scene.)
//
// Cost, per plane of H x W: a separable term (the Gaussians) two 1-D passes,
// H W (2 rx + 1) + H W (2 ry + 1) multiply-adds; an image term either the
// direct sum over the lit pixels, lit x (2 rx + 1)(2 ry + 1), or a 2-D FFT of
// the zero-padded plane (sizes the powers of two >= H + ry and W + rx; two
// planes share one complex transform), whichever is estimated cheaper. The
// kernel is cropped to offsets < the image's size first, which changes
// nothing inside the image. All-zero planes (most of a transient's bins) are
// skipped. Measured on one core (tests/optics PsfTimingTest prints it).

#include <cstddef>
#include <cstdint>

#include "tofsim/optics/PsfKernel.h"

namespace tofsim::optics {

/// Where plane p's pixel (x, y) lies: values[p * planeStride + (y * width +
/// x) * pixelStride]. Contiguous planes: pixelStride 1, planeStride H W; a
/// transient (H, W, T, C): pixelStride T C, planeStride 1 (plane t C + c).
struct PlaneLayout {
  int32_t width = 0, height = 0;
  std::size_t pixelStride = 1;
  std::size_t planeStride = 0;
};

/// Auto: the separable terms in 1-D passes, each image term direct or by FFT
/// as cheaper. Direct and Fft take the whole kernel as one image (K.image()),
/// summed directly or through the FFT: the oracles the tests compare with.
enum class PsfMethod { Auto, Direct, Fft };

struct PsfOptions {
  PsfMethod method = PsfMethod::Auto;
  /// Worker threads over the planes (0 = every core); the bytes do not
  /// depend on it (each plane, or FFT pair of planes, is one task).
  int threads = 1;
};

/// Convolves `planes` planes in place (computed in double, written back
/// once). Values must be finite (the pipeline's FiniteSegments cleans them
/// first): a NaN would spread over its kernel's support.
void applyPsf(const PsfKernel& kernel, float* values, std::size_t planes, const PlaneLayout& layout,
              const PsfOptions& options = {});
void applyPsf(const PsfKernel& kernel, double* values, std::size_t planes,
              const PlaneLayout& layout, const PsfOptions& options = {});

/// `count` contiguous H x W planes (row-major, y = 0 at the top), as a CW-ToF
/// sensor holds its F x N noise-free raw images: the lens's scattering of
/// the correlation signal, identical by linearity to convolving every time
/// bin of the transient before correlating, and far cheaper.
void applyPsf(const PsfKernel& kernel, float* planes, int32_t count, int32_t height, int32_t width);
void applyPsf(const PsfKernel& kernel, double* planes, int32_t count, int32_t height,
              int32_t width);

}  // namespace tofsim::optics
