// The gathers' side of the pixel footprint (render.pixel_footprint): a
// contribution spread by its kernel (footprint_kernel.glsl) goes straight into
// the float histogram when narrow, else into the segment's difference buffer
// of doubles, which footprint_integrate.comp turns into bin integrals once per
// pixel. The steps and float operations of depositContribution in
// core/physics/include/tofsim/physics/FootprintBuffer.h, so the GL and CPU
// volumes agree to float rounding.
//
// The including gather defines GATHER_HISTOGRAM (the name of its float
// volume array, bin_deposit.glsl) and declares uBins. A sample's
// footprint is its sub-pixel (uSampleStepX/Y), or with ADAPTIVE_SAMPLES, for a
// masked-out pixel's one centre sample, the whole pixel (uPixelStepX/Y). With
// SURFACE_STEPS (a point-set imager, capture::PixelSteps) these are the
// surface's steps themselves, the same at every sample; else they are the
// camera's ray steps, carried to each sample's tangent plane: the pinhole's,
// the same for every pixel, or with PIXEL_RAY_STEPS (a camera with a lens)
// each pixel's own (Camera::rayStepsAt), from a buffer.
//
// llvmpipe ends every loop of an invocation after 65535 iterations in total
// (see indirect_gather.comp): the up to FOOTPRINT_DIRECT_BINS narrow bins and
// the FOOTPRINT_SLOTS slots are written as straight-line calls, not loops, so
// a contribution costs the gather's loop guard nothing. GlBackend.cpp checks
// both counts at compile time.
#ifndef TOFSIM_FOOTPRINT_DEPOSIT_GLSL
#define TOFSIM_FOOTPRINT_DEPOSIT_GLSL

#include "bin_deposit.glsl"
#include "footprint_kernel.glsl"

// Per pixel of the segment: bins x TOFSIM_CHANNELS doubles, (bin, channel).
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT) buffer FootprintDiff { double footprintDiff[]; };
// Per pixel: 1 once a wide kernel wrote its difference buffer (the
// integration skips the others, as the CPU's footprintBins_, which also keeps
// the bins written).
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT_WRITTEN) buffer FootprintWritten {
  uint footprintWritten[];
};

#ifndef SURFACE_STEPS
uniform vec3 uCameraForward;  // the camera's unit view axis
#endif
#ifdef PIXEL_RAY_STEPS
// Per image pixel: its ray steps along x, then along y (xyz), unscaled.
layout(std430, binding = TOFSIM_SSBO_PIXEL_RAY_STEPS) readonly buffer PixelRaySteps {
  vec4 pixelRaySteps[];
};
#else
uniform vec3 uSampleStepX;    // Camera::rayStepAlongX() / pixel_samples: one sub-pixel step
uniform vec3 uSampleStepY;    // Camera::rayStepAlongY() / pixel_samples
#ifdef ADAPTIVE_SAMPLES
// Camera::rayStepAlongX() / Y(), unscaled: the step of a masked-out pixel's
// one centre sample, whose footprint is the whole pixel (surface_samples.glsl).
uniform vec3 uPixelStepX;
uniform vec3 uPixelStepY;
#endif
#endif

// The surface point's steps across the sample's footprint (dx/du, dx/dv),
// from the ray differentials on its tangent plane: the sample's sub-pixel, or
// with wholePixel (only with ADAPTIVE_SAMPLES) the whole pixel. The rays
// start at `camera`, the sample's camera end (camera_end.glsl).
void surfaceStepsAcrossSample(vec3 x, vec3 n, vec3 camera, ivec2 pixel, bool wholePixel,
                              out vec3 dxdu, out vec3 dxdv) {
  vec3 toSurface = x - camera;
#ifdef PIXEL_RAY_STEPS
  // The CPU's PixelSteps: the pixel's steps times the side 1 / N of a
  // sub-pixel, or 1 for a whole-pixel sample.
  uint i = 2u * uint(pixel.y * uImageWidth + pixel.x);
  float side = wholePixel ? 1.0 : 1.0 / float(PIXEL_SAMPLES);
  vec3 stepX = pixelRaySteps[i].xyz * side;
  vec3 stepY = pixelRaySteps[i + 1u].xyz * side;
#else
  vec3 stepX = uSampleStepX;
  vec3 stepY = uSampleStepY;
#ifdef ADAPTIVE_SAMPLES
  if (wholePixel) {
    stepX = uPixelStepX;
    stepY = uPixelStepY;
  }
#endif
#endif
#ifdef SURFACE_STEPS
  dxdu = stepX;
  dxdv = stepY;
#else
  dxdu = surfaceStepAcrossPixel(toSurface, uCameraForward, stepX, n);
  dxdv = surfaceStepAcrossPixel(toSurface, uCameraForward, stepY, n);
#endif
}

// Narrow kernel: bin first + j (j < count) gets the mass between its edges
// times energy in the histogram, or off the axis (physics::depositInBin).
// `lower` carries the CDF at the bin's lower edge from the previous bin, so
// each edge is evaluated once: footprintNarrowMass(kernel, j) bit for bit.
void footprintAddNarrowBin(uint local, vec3 kernel, int first, int count, int j, vec3 energy,
                           inout float lower, inout float lostBefore, inout float lostAfter) {
  if (j >= count) return;
  float upper = footprintNarrowEdgeCdf(kernel, j);
  float mass = upper - lower;
  lower = upper;
  depositInBin(local, first + j, mass, energy, lostBefore, lostAfter);
}

// Wide kernel: slot `slot` of the difference buffer of `region`
// (footprintSlotBin, footprintSlotValue; physics::depositFootprint).
void footprintAddSlot(uint region, vec3 kernel, int slot, vec3 energy) {
  int bin = footprintSlotBin(kernel, slot, uBins);
  if (bin < 0) return;
  double value = footprintSlotValue(kernel, bin);
  uint i = (region * uint(uBins) + uint(bin)) * uint(TOFSIM_CHANNELS);
  footprintDiff[i + 0u] += value * double(energy.r);
  footprintDiff[i + 1u] += value * double(energy.g);
  footprintDiff[i + 2u] += value * double(energy.b);
}

#define TOFSIM_NARROW_BIN(j) \
  footprintAddNarrowBin(local, kernel, first, count, j, energy, lower, lostBefore, lostAfter)
#define TOFSIM_SLOT(s) footprintAddSlot(region, kernel, s, energy)

// A kernel into the difference buffer of `region` (pixel `local` of the
// segment, or a delayed class's pixel), exact however narrow; the part off the
// axis to lostBefore / lostAfter (physics::depositWide).
void depositWideAt(uint region, vec3 kernel, vec3 energy, inout float lostBefore,
                   inout float lostAfter) {
  // FOOTPRINT_SLOTS (12): three per kink, in increasing bin order.
  TOFSIM_SLOT(0); TOFSIM_SLOT(1); TOFSIM_SLOT(2); TOFSIM_SLOT(3);
  TOFSIM_SLOT(4); TOFSIM_SLOT(5); TOFSIM_SLOT(6); TOFSIM_SLOT(7);
  TOFSIM_SLOT(8); TOFSIM_SLOT(9); TOFSIM_SLOT(10); TOFSIM_SLOT(11);
  float total = energy.r + energy.g + energy.b;
  double before = footprintMassBefore(kernel);
  double after = footprintMassAfter(kernel, uBins);
  if (before > 0.0lf) lostBefore += float(before) * total;
  if (after > 0.0lf) lostAfter += float(after) * total;
  footprintWritten[region] = 1u;
}

// Adds a contribution of `energy` spread by `kernel` to pixel `local` of the
// segment; the part off the axis to lostBefore / lostAfter
// (physics::depositContribution: the same steps and float operations).
void depositContribution(uint local, vec3 kernel, vec3 energy, inout float lostBefore,
                         inout float lostAfter) {
  if (!footprintIsNarrow(kernel)) {
    depositWideAt(local, kernel, energy, lostBefore, lostAfter);
    return;
  }
  // FOOTPRINT_DIRECT_BINS (16) bins at most, ascending.
  int first = footprintNarrowFirstBin(kernel, uBins);
  int count = footprintNarrowBinCount(kernel);
  float lower = 0.0f;
  TOFSIM_NARROW_BIN(0); TOFSIM_NARROW_BIN(1); TOFSIM_NARROW_BIN(2); TOFSIM_NARROW_BIN(3);
  TOFSIM_NARROW_BIN(4); TOFSIM_NARROW_BIN(5); TOFSIM_NARROW_BIN(6); TOFSIM_NARROW_BIN(7);
  TOFSIM_NARROW_BIN(8); TOFSIM_NARROW_BIN(9); TOFSIM_NARROW_BIN(10); TOFSIM_NARROW_BIN(11);
  TOFSIM_NARROW_BIN(12); TOFSIM_NARROW_BIN(13); TOFSIM_NARROW_BIN(14); TOFSIM_NARROW_BIN(15);
}

#ifdef RESPONSE_CLASSES
// The delayed response classes (core/physics/temporal_response.md): class c
// >= 1 owns region c of the difference buffer, uResponseRegionPixels pixels
// after region c - 1 (region 0 is the instant class's, the segment's pixels).
uniform uint uResponseRegionPixels;

// A contribution of delayed class `responseClass` (>= 1) to pixel `local`:
// into its class's difference buffer whatever its width, which
// response_integrate.comp filters by the class's kernel
// (cpu::ResponseClasses::deposit: the same entries).
void depositDelayed(uint local, uint responseClass, vec3 kernel, vec3 energy,
                    inout float lostBefore, inout float lostAfter) {
  depositWideAt(responseClass * uResponseRegionPixels + local, kernel, energy, lostBefore,
                lostAfter);
}
#endif

#undef TOFSIM_NARROW_BIN
#undef TOFSIM_SLOT

#endif  // TOFSIM_FOOTPRINT_DEPOSIT_GLSL
