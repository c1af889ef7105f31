// The gathers' side of the pixel footprint (render.pixel_footprint): a
// contribution spread by its kernel (footprint_kernel.glsl) goes straight into
// the float histogram when narrow, else into the segment's difference buffer
// of doubles, which footprint_integrate.comp turns into bin integrals once per
// pixel. The steps and float operations of depositContribution in
// core/physics/include/tofsim/physics/FootprintBuffer.h, so the GL and CPU
// volumes agree to float rounding.
//
// The including gather defines FOOTPRINT_HISTOGRAM (the name of its float
// volume array) and declares uBins and uCameraPosition_world.
//
// llvmpipe ends every loop of an invocation after 65535 iterations in total
// (see indirect_gather.comp): the up to FOOTPRINT_DIRECT_BINS narrow bins and
// the FOOTPRINT_SLOTS slots are written as straight-line calls, not loops, so
// a contribution costs the gather's loop guard nothing. GlBackend.cpp checks
// both counts at compile time.
#ifndef TOFSIM_FOOTPRINT_DEPOSIT_GLSL
#define TOFSIM_FOOTPRINT_DEPOSIT_GLSL

#include "footprint_kernel.glsl"

// Per pixel of the segment: bins x TOFSIM_CHANNELS doubles, (bin, channel).
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT) buffer FootprintDiff { double footprintDiff[]; };
// Per pixel: 1 once a wide kernel wrote its difference buffer (the
// integration skips the others, as the CPU's footprintWritten_).
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT_WRITTEN) buffer FootprintWritten {
  uint footprintWritten[];
};

uniform vec3 uCameraForward;  // the camera's unit view axis
uniform vec3 uSampleStepX;    // Camera::rayStepAlongX() / pixel_samples: one sub-pixel step
uniform vec3 uSampleStepY;    // Camera::rayStepAlongY() / pixel_samples

// The surface point's steps across the sample's sub-pixel (dx/du, dx/dv),
// from the ray differentials on its tangent plane.
void surfaceStepsAcrossSample(vec3 x, vec3 n, out vec3 dxdu, out vec3 dxdv) {
  vec3 toSurface = x - uCameraPosition_world;
  dxdu = surfaceStepAcrossPixel(toSurface, uCameraForward, uSampleStepX, n);
  dxdv = surfaceStepAcrossPixel(toSurface, uCameraForward, uSampleStepY, n);
}

// The deposits below evaluate the kernel's CDF once per bin edge they need
// (5 for a narrow kernel, 6 per kink for a wide one) instead of once per term
// as footprintBinMass and footprintSlotValue do (8 and 96), with the same
// double operations on the same values, so the bytes are theirs
// (FootprintDepositGLTest checks this against physics::depositContribution).

// Narrow kernel: adds the mass between bin edges k and k + 1 (cdfLo, cdfHi)
// times energy to bin k of the histogram, when k is within range (the support
// clamped to the axis).
void footprintAddBin(uint local, int k, ivec2 range, double cdfLo, double cdfHi, vec3 energy) {
  if (k > range.y) return;
  float mass = float(cdfHi - cdfLo);  // footprintBinMass
  uint i = (local * uint(uBins) + uint(k)) * uint(TOFSIM_CHANNELS);
  FOOTPRINT_HISTOGRAM[i + 0u] += mass * energy.r;
  FOOTPRINT_HISTOGRAM[i + 1u] += mass * energy.g;
  FOOTPRINT_HISTOGRAM[i + 2u] += mass * energy.b;
}

// Wide kernel: adds value * energy at difference-buffer bin k, unless the
// slot writes nothing (footprintSlotBin's rules: past the axis, or a bin the
// previous kink's slots wrote, i.e. k <= last).
void footprintAddEntry(uint local, int k, int last, double value, vec3 energy) {
  if (k >= uBins || k <= last) return;
  uint i = (local * uint(uBins) + uint(k)) * uint(TOFSIM_CHANNELS);
  footprintDiff[i + 0u] += value * double(energy.r);
  footprintDiff[i + 1u] += value * double(energy.g);
  footprintDiff[i + 2u] += value * double(energy.b);
}

// The on-axis cumulative G(i) = F(max(i, 0)) - F(0) (footprintMassToEdge),
// with F(0) given.
double footprintEdgeMass(vec3 kernel, int i, double cdfZero) {
  return footprintCdf(kernel, double(max(i, 0))) - cdfZero;
}

// Wide kernel: the three slots of kink `knot`, at bins b, b + 1, b + 2 (b its
// bin), each D_k = G(k+1) - 3 G(k) + 3 G(k-1) - G(k-2) (footprintSlotValue).
// `last` is the last bin the previous kink's slots covered (-1 for the
// first). Returns this kink's last bin.
int footprintAddKnot(uint local, vec3 kernel, int knot, int last, double cdfZero, vec3 energy) {
  int b = footprintKnotBin(kernel, knot, uBins);
  double g0 = footprintEdgeMass(kernel, b - 2, cdfZero);
  double g1 = footprintEdgeMass(kernel, b - 1, cdfZero);
  double g2 = footprintEdgeMass(kernel, b, cdfZero);
  double g3 = footprintEdgeMass(kernel, b + 1, cdfZero);
  double g4 = footprintEdgeMass(kernel, b + 2, cdfZero);
  double g5 = footprintEdgeMass(kernel, b + 3, cdfZero);
  double three = double(3.0f);
  footprintAddEntry(local, b, last, g3 - three * g2 + three * g1 - g0, energy);
  footprintAddEntry(local, b + 1, last, g4 - three * g3 + three * g2 - g1, energy);
  footprintAddEntry(local, b + 2, last, g5 - three * g4 + three * g3 - g2, energy);
  return b + 2;
}

// Adds a contribution of `energy` spread by `kernel` to pixel `local` of the
// segment; the part off the axis to lostBefore / lostAfter.
void depositContribution(uint local, vec3 kernel, vec3 energy, inout float lostBefore,
                         inout float lostAfter) {
  float total = energy.r + energy.g + energy.b;
  ivec2 support = footprintSupport(kernel, uBins);
  if (!footprintIsNarrow(support)) {
    // FOOTPRINT_SLOTS (12): three per kink, in increasing bin order; none
    // for a kernel wholly off the axis.
    double cdfZero = footprintCdf(kernel, double(0.0f));
    if (footprintKnot(kernel, 3) >= double(0.0f) && footprintKnot(kernel, 0) < double(uBins)) {
      int last = footprintAddKnot(local, kernel, 0, -1, cdfZero, energy);
      last = footprintAddKnot(local, kernel, 1, last, cdfZero, energy);
      last = footprintAddKnot(local, kernel, 2, last, cdfZero, energy);
      footprintAddKnot(local, kernel, 3, last, cdfZero, energy);
    }
    double before = cdfZero;  // footprintMassBefore
    double after = footprintMassAfter(kernel, uBins);
    if (before > 0.0lf) lostBefore += float(before) * total;
    if (after > 0.0lf) lostAfter += float(after) * total;
    footprintWritten[local] = 1u;
    return;
  }
  if (support.x < 0) lostBefore += float(footprintMassBefore(kernel)) * total;
  // At most FOOTPRINT_DIRECT_BINS (4) bins, ascending.
  ivec2 range = ivec2(max(support.x, 0), min(support.y, uBins - 1));
  double f0 = footprintCdf(kernel, double(range.x));
  double f1 = footprintCdf(kernel, double(range.x + 1));
  double f2 = footprintCdf(kernel, double(range.x + 2));
  double f3 = footprintCdf(kernel, double(range.x + 3));
  double f4 = footprintCdf(kernel, double(range.x + 4));
  footprintAddBin(local, range.x, range, f0, f1, energy);
  footprintAddBin(local, range.x + 1, range, f1, f2, energy);
  footprintAddBin(local, range.x + 2, range, f2, f3, energy);
  footprintAddBin(local, range.x + 3, range, f3, f4, energy);
  if (support.y >= uBins) lostAfter += float(footprintMassAfter(kernel, uBins)) * total;
}

#endif  // TOFSIM_FOOTPRINT_DEPOSIT_GLSL
