// The pixel footprint in time, written once in the common subset of GLSL 4.50
// and C++/GLM (the rules of transient_physics.glsl): the GL gathers include
// this file, C++ includes it through
// core/physics/include/tofsim/physics/FootprintKernel.h. The construction and
// its assumptions are in core/physics/footprint_kernel.md.
//
// A pixel integrates over its area. Across the pixel the optical path is, to
// first order, linear in the sub-pixel offset (u, v) in [-1/2, 1/2]^2:
// path = p0 + a u + b v. Its distribution is the convolution of two boxes of
// widths |a| and |b|: a trapezoid (a box when one width is 0, a spike when
// both are). A contribution is spread over the time bins by that kernel, in
// closed form, at a cost independent of its width in bins: the deposit writes
// the kernel's second differences into a per-pixel difference buffer, only
// near the kernel's four kinks, and one double prefix sum per pixel at the end
// turns the buffer into exact bin integrals.
//
// Units: a kernel is a vec3 in bins of the time axis: x = centre (the path's
// offset from the axis start, in bins: the same quotient binOfPath floors),
// y = the wider box width, z = the narrower one (y >= z >= 0). The cumulative
// distribution and the deposit values are doubles: the double prefix sum
// amplifies an entry's rounding by the distance to the end of the axis, so
// entries must be good to far more than float's 24 bits (see the notes).
#ifndef TOFSIM_FOOTPRINT_KERNEL_GLSL
#define TOFSIM_FOOTPRINT_KERNEL_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

// Difference-buffer entries one contribution writes at most: three per kink.
const int FOOTPRINT_SLOTS = 12;

// v / |v|, or 0 for the zero vector.
TOFSIM_PHYSICS_FN vec3 footprintUnitOrZero(vec3 v) {
  float len = length(v);
  float scale = len > 0.0f ? 1.0f / len : 0.0f;  // a select, not a branch: vectorises
  return v * scale;
}

// Derivative of the surface point x across one pixel step, from the ray
// differential on the surface's tangent plane. toSurface = x - camera;
// forward = the camera's unit view axis; dirStep = the change of the camera
// ray's unnormalised direction (forward + s right + t up) over one pixel step
// (right * 2 tan(fov_y/2) / height for u, -up * 2 tan(fov_y/2) / height for
// v); n = the surface normal (either side). Exactly grazing rays are held at a
// cosine of 1e-6 instead of dividing by zero.
TOFSIM_PHYSICS_FN vec3 surfaceStepAcrossPixel(vec3 toSurface, vec3 forward, vec3 dirStep, vec3 n) {
  float t = dot(toSurface, forward);  // the ray parameter of x for that direction
  float facing = dot(n, toSurface);
  float least = 1e-6f * length(toSurface);
  if (abs(facing) < least) facing = facing < 0.0f ? -least : least;
  return t * (dirStep - toSurface * (dot(n, dirStep) / facing));
}

// Gradient in x of the optical path eta * (|x - source| + |x - camera|), the
// camera leg dropped when the camera delay is unwarped. source = the point
// light for the direct term, the VPL for an indirect one (the VPL's own path
// t_l is constant across the pixel).
TOFSIM_PHYSICS_FN vec3 opticalPathGradient(vec3 x, vec3 source, vec3 camera, float eta,
                                           bool unwarp) {
  float cameraLeg = unwarp ? 0.0f : 1.0f;
  return eta * (footprintUnitOrZero(x - source) + cameraLeg * footprintUnitOrZero(x - camera));
}

// The path's derivatives (a, b) in metres across the pixel: the gradient
// projected on the surface steps dx/du and dx/dv.
TOFSIM_PHYSICS_FN vec2 pathStepsAcrossPixel(vec3 gradient, vec3 dxdu, vec3 dxdv) {
  return vec2(dot(gradient, dxdu), dot(gradient, dxdv));
}

// The path's derivatives (c, d) in metres across a VPL's patch (its RSM
// texel, spanned by patchU.xyz and patchV.xyz), toward the point x in
// direction d = (x - x_l) / |x - x_l|: the gradient in x_l of
// eta (|x_l - l| + |x_l - x|) projected on the patch steps. The light leg's
// part, eta (x_l - l)/|x_l - l| . step, is constant per VPL and stored in the
// steps' w (vplPatchSteps in core/ir).
TOFSIM_PHYSICS_FN vec2 vplPatchPathSteps(vec4 patchU, vec4 patchV, vec3 d, float eta) {
  return vec2(patchU.w - eta * dot(d, vec3(patchU)), patchV.w - eta * dot(d, vec3(patchV)));
}

// The two box widths (bins) standing for a path linear in four independent
// uniform offsets: the pixel's (u, v) with derivatives steps_m.xy and the
// VPL patch's with steps_m.zw (0 for the direct term). Their sum's density is
// the convolution of four boxes; it is replaced by the trapezoid of the two
// boxes with the same mean and variance that keeps the widest box: wide = the
// largest width, narrow = the root sum of squares of the other three (then
// (wide^2 + narrow^2) / 12 is the variance of the sum); if that exceeds wide,
// both get the root mean square. With the patch's widths 0 this is exactly
// the pixel's trapezoid (sqrt(b * b) == |b| in IEEE arithmetic), so the direct
// term and a VPL without a footprint are spread exactly as derived above.
TOFSIM_PHYSICS_FN vec2 footprintWidths(vec4 steps_m, float binWidth_m) {
  vec4 w = abs(steps_m) / binWidth_m;
  float pixelWide = max(w.x, w.y);
  float pixelNarrow = min(w.x, w.y);
  float patchWide = max(w.z, w.w);
  float patchNarrow = min(w.z, w.w);
  float wide = max(pixelWide, patchWide);
  float other = min(pixelWide, patchWide);
  float narrow = sqrt(other * other + pixelNarrow * pixelNarrow + patchNarrow * patchNarrow);
  float rms = sqrt(0.5f * (wide * wide + narrow * narrow));
  bool equal = narrow > wide;  // selects, not branches: vectorises
  return vec2(equal ? rms : wide, equal ? rms : narrow);
}

// The kernel (see the top) of a contribution at optical path path_m whose
// path changes by steps_m across the pixel (xy) and across the VPL's patch
// (zw; 0 without one), on the axis (start_m, binWidth_m).
TOFSIM_PHYSICS_FN vec3 footprintKernel(float path_m, vec4 steps_m, float start_m,
                                       float binWidth_m) {
  vec2 widths = footprintWidths(steps_m, binWidth_m);
  return vec3((path_m - start_m) / binWidth_m, widths.x, widths.y);
}
TOFSIM_PHYSICS_FN vec3 footprintKernel(float path_m, vec2 steps_m, float start_m,
                                       float binWidth_m) {
  return footprintKernel(path_m, vec4(steps_m.x, steps_m.y, 0.0f, 0.0f), start_m, binWidth_m);
}

// Position (bins) of kink `knot` (0..3, in increasing order): the trapezoid's
// start, the end of its rising ramp, the start of its falling ramp, its end.
TOFSIM_PHYSICS_FN double footprintKnot(vec3 kernel, int knot) {
  double halfSum = (double(kernel.y) + double(kernel.z)) * double(0.5f);
  double halfDiff = (double(kernel.y) - double(kernel.z)) * double(0.5f);
  double offset =
      knot == 0 ? -halfSum : (knot == 1 ? -halfDiff : (knot == 2 ? halfDiff : halfSum));
  return double(kernel.x) + offset;
}

// Fraction of the kernel's mass below x (bins): 0, a quadratic rise, linear,
// a quadratic approach to 1. A spike (both widths 0) at centre c puts its mass
// in the bin [floor(c), floor(c) + 1), as point sampling does: F(x) = x > c.
TOFSIM_PHYSICS_FN double footprintCdf(vec3 kernel, double x) {
  double zero = double(0.0f);
  double one = double(1.0f);
  double wide = double(kernel.y);
  double narrow = double(kernel.z);
  double s = x - footprintKnot(kernel, 0);
  if (s <= zero) return zero;
  if (s >= wide + narrow) return one;
  if (s < narrow) return s * s / (double(2.0f) * wide * narrow);  // rising ramp
  if (s <= wide) return (s - double(0.5f) * narrow) / wide;       // plateau
  double r = wide + narrow - s;                                   // falling ramp
  return one - r * r / (double(2.0f) * wide * narrow);
}

// Mass of the kernel before the axis (bins < 0) and after it (bins >= bins):
// the energy the caller books as off the axis.
TOFSIM_PHYSICS_FN double footprintMassBefore(vec3 kernel) {
  return footprintCdf(kernel, double(0.0f));
}
TOFSIM_PHYSICS_FN double footprintMassAfter(vec3 kernel, int bins) {
  return double(1.0f) - footprintCdf(kernel, double(bins));
}

// Mass between the axis start and bin edge i, the on-axis cumulative G(i):
// 0 for i <= 0. Truncating at the start makes bins before the axis hold 0, so
// the prefix sums can start at bin 0.
TOFSIM_PHYSICS_FN double footprintMassToEdge(vec3 kernel, int i) {
  int edge = max(i, 0);
  return footprintCdf(kernel, double(edge)) - footprintCdf(kernel, double(0.0f));
}

// Bin of kink `knot`, clamped to [0, bins].
TOFSIM_PHYSICS_FN int footprintKnotBin(vec3 kernel, int knot, int bins) {
  double b = clamp(floor(footprintKnot(kernel, knot)), double(0.0f), double(bins));
  return int(b);
}

// Difference-buffer bin written by deposit slot `slot` (0 .. FOOTPRINT_SLOTS-1),
// or -1 when the slot writes nothing. Slot 3 j + o is bin knotBin(j) + o: the
// second difference D_k = I_k - 2 I_(k-1) + I_(k-2) of the bin integrals I can
// only be non-zero where a kink lies in bins k-2 .. k (elsewhere the density is
// linear over the three bins, so their integrals are collinear). A bin already
// written by the previous kink's slots is skipped, so each bin is written once
// per contribution, and the bins come in increasing order.
TOFSIM_PHYSICS_FN int footprintSlotBin(vec3 kernel, int slot, int bins) {
  if (footprintKnot(kernel, 3) < double(0.0f) || footprintKnot(kernel, 0) >= double(bins)) {
    return -1;  // wholly off the axis
  }
  int knot = slot / 3;
  int bin = footprintKnotBin(kernel, knot, bins) + (slot - 3 * knot);
  if (bin >= bins) return -1;
  if (knot > 0 && bin <= footprintKnotBin(kernel, knot - 1, bins) + 2) return -1;
  return bin;
}

// The value a deposit adds at difference-buffer bin k, per unit of energy,
// from the CDF: D_k = I_k - 2 I_(k-1) + I_(k-2), I_i = G(i + 1) - G(i), so
// D_k = G(k+1) - 3 G(k) + 3 G(k-1) - G(k-2), all exact. Used where the kernel
// starts near or before the axis (the truncation of G at the start).
TOFSIM_PHYSICS_FN double footprintSlotValueFromCdf(vec3 kernel, int k) {
  double three = double(3.0f);
  return footprintMassToEdge(kernel, k + 1) - three * footprintMassToEdge(kernel, k) +
         three * footprintMassToEdge(kernel, k - 1) - footprintMassToEdge(kernel, k - 2);
}

// What one kink of the density contributes to D_k. The trapezoid's density
// is piecewise linear; at a kink at p its slope changes by s, and a ramp
// s max(x - p, 0) has bin integrals whose second differences are s times the
// quadratic B-spline B2(k + 1 - p) (support [0, 3], sum 1). A box (narrow
// width under 1e-6 bins) has steps instead: a step h H(x - p) gives h (1 - f),
// h (2 f - 1), -h f at bins floor(p) + 0, 1, 2 (f = p - floor(p)).
TOFSIM_PHYSICS_FN double footprintKinkWeight(double p, int k, bool step) {
  double zero = double(0.0f);
  double oneHalf = double(0.5f);
  double t = double(k + 1) - p;  // in (0, 3] on the kink's three bins
  if (t <= zero || t > double(3.0f)) return zero;
  if (step) {
    double f = double(1.0f) - t + floor(t);  // p - floor(p), as t = k + 1 - p
    if (t <= double(1.0f)) return t;         // bin floor(p): 1 - f
    if (t <= double(2.0f)) return double(2.0f) * f - double(1.0f);
    return -f;
  }
  if (t <= double(1.0f)) return oneHalf * t * t;
  if (t <= double(2.0f)) {
    return oneHalf * (double(-2.0f) * t * t + double(6.0f) * t - double(3.0f));
  }
  double r = double(3.0f) - t;
  return oneHalf * r * r;
}

// The value a deposit adds at difference-buffer bin k, per unit of energy.
// For a kernel at least a bin wide away from the axis start, the sum of the
// four kinks' B-spline weights (a few flops instead of 24 CDF values, exact
// for the trapezoid; the renderers deposit only kernels wider than
// FOOTPRINT_DIRECT_BINS here, narrower ones go straight to the histogram,
// below); else from the truncated CDF, which is accurate however narrow.
TOFSIM_PHYSICS_FN double footprintSlotValue(vec3 kernel, int k) {
  double wide = double(kernel.y);
  if (footprintKnot(kernel, 0) < double(2.0f) || wide < double(1.0f)) {
    return footprintSlotValueFromCdf(kernel, k);
  }
  double narrow = double(kernel.z);
  bool step = narrow < double(1e-6f);
  // Slope changes +1/(AB), -1/(AB), -1/(AB), +1/(AB) at kinks 0..3, or
  // steps +1/A at kink 0 and -1/A at kink 3 for a box.
  double ramp = step ? double(0.0f) : double(1.0f) / (wide * narrow);
  double height = double(1.0f) / wide;
  if (step) {
    return height * (footprintKinkWeight(footprintKnot(kernel, 0), k, true) -
                     footprintKinkWeight(footprintKnot(kernel, 3), k, true));
  }
  return ramp * (footprintKinkWeight(footprintKnot(kernel, 0), k, false) -
                 footprintKinkWeight(footprintKnot(kernel, 1), k, false) -
                 footprintKinkWeight(footprintKnot(kernel, 2), k, false) +
                 footprintKinkWeight(footprintKnot(kernel, 3), k, false));
}

// ---- Narrow kernels: straight into the histogram, in float ----
//
// Most contributions cover a few bins (a wall seen head-on: under one). For
// them the difference buffer would cost more than it saves (about 25 CDF
// values in double and a per-pixel integration), so a kernel whose support
// touches at most FOOTPRINT_DIRECT_BINS bins adds its bin masses straight to
// the float histogram; wider ones go to the difference buffer. Which way a
// contribution goes depends on it alone, so the bytes stay deterministic.
//
// Narrow masses are computed in float, branch-free (the CPU vectorises them,
// a GPU runs float at full rate): the bin integrals of a kernel inside 8 bins
// need no more than float, the kink positions' own precision is that of the
// float path whose bin point sampling takes, and the CDF is exactly 0 below
// the support's first bin edge and exactly 1 above its last bin, so a kernel
// inside one bin (a spike, a wall seen head-on) puts exactly its value there.
const int FOOTPRINT_DIRECT_BINS = 16;

// The kernel's first and last kink relative to floor(centre), in float:
// exact offsets from the centre's bin, so the kinks' positions within it are
// good to float's precision near 1 whatever the centre (its own bin has the
// precision of the path's float, as in point sampling).
TOFSIM_PHYSICS_FN vec2 footprintLocalExtent(vec3 kernel) {
  float halfWidth = 0.5f * (kernel.y + kernel.z);
  float local = kernel.x - floor(kernel.x);  // exact
  return vec2(local - halfWidth, local + halfWidth);
}

// Whether the kernel's support touches at most FOOTPRINT_DIRECT_BINS bins.
TOFSIM_PHYSICS_FN bool footprintIsNarrow(vec3 kernel) {
  vec2 e = footprintLocalExtent(kernel);
  return floor(e.y) - floor(e.x) < float(FOOTPRINT_DIRECT_BINS);
}

// Bins a narrow kernel touches: from footprintNarrowFirstBin, this many.
TOFSIM_PHYSICS_FN int footprintNarrowBinCount(vec3 kernel) {
  vec2 e = footprintLocalExtent(kernel);
  return int(floor(e.y) - floor(e.x)) + 1;
}

// The first bin a narrow kernel touches (may lie off the axis). Clamped to
// [-FOOTPRINT_DIRECT_BINS - 1, bins] so that a kernel far off the axis (its
// masses then all land off it) keeps the integer in range.
TOFSIM_PHYSICS_FN int footprintNarrowFirstBin(vec3 kernel, int bins) {
  float first = floor(kernel.x) + floor(footprintLocalExtent(kernel).x);
  return int(clamp(first, -float(FOOTPRINT_DIRECT_BINS) - 1.0f, float(bins)));
}

// The kernel's CDF at s bins above its first kink, without branches.
TOFSIM_PHYSICS_FN float footprintNarrowCdf(vec3 kernel, float s) {
  float wide = kernel.y;
  float narrow = kernel.z;
  float total = wide + narrow;
  // Reciprocals: the same for every edge of a kernel, so the compilers
  // compute them once per contribution, and each edge costs multiplies only.
  float perRamps = 1.0f / (2.0f * wide * narrow);
  float perWide = 1.0f / wide;
  float rising = s * s * perRamps;
  float plateau = (s - 0.5f * narrow) * perWide;
  float r = total - s;
  float falling = 1.0f - r * r * perRamps;
  float inside = s < narrow ? rising : (s <= wide ? plateau : falling);
  return s <= 0.0f ? 0.0f : (s >= total ? 1.0f : inside);
}

// The narrow kernel's CDF at the upper edge of bin first + j
// (first = footprintNarrowFirstBin): exactly 1 above its last bin. Off the
// axis by far, `first` was clamped: the masses then only need to sum to 1,
// which the exact 0 below and 1 above guarantee.
TOFSIM_PHYSICS_FN float footprintNarrowEdgeCdf(vec3 kernel, int j) {
  vec2 e = footprintLocalExtent(kernel);
  float frac = e.x - floor(e.x);  // the first kink's position in its bin
  float last = floor(e.y) - floor(e.x);
  return float(j + 1) > last ? 1.0f : footprintNarrowCdf(kernel, float(j + 1) - frac);
}

// Mass of a narrow kernel in bin first + j (0 <= j < footprintNarrowBinCount):
// the factor of the contribution's value added to that bin, or booked before
// / after the axis when it lies there.
TOFSIM_PHYSICS_FN float footprintNarrowMass(vec3 kernel, int j) {
  float lower = j == 0 ? 0.0f : footprintNarrowEdgeCdf(kernel, j - 1);
  return footprintNarrowEdgeCdf(kernel, j) - lower;
}

#endif  // TOFSIM_FOOTPRINT_KERNEL_GLSL
