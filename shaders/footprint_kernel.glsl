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
  return len > 0.0f ? v / len : vec3(0.0f);
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
  vec3 g = footprintUnitOrZero(x - source);
  if (!unwarp) g = g + footprintUnitOrZero(x - camera);
  return eta * g;
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
  if (narrow > wide) {
    float rms = sqrt(0.5f * (wide * wide + narrow * narrow));
    return vec2(rms, rms);
  }
  return vec2(wide, narrow);
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

// The value a deposit adds at difference-buffer bin k, per unit of energy:
// D_k = I_k - 2 I_(k-1) + I_(k-2), I_i = G(i + 1) - G(i), so
// D_k = G(k+1) - 3 G(k) + 3 G(k-1) - G(k-2), all exact.
TOFSIM_PHYSICS_FN double footprintSlotValue(vec3 kernel, int k) {
  double three = double(3.0f);
  return footprintMassToEdge(kernel, k + 1) - three * footprintMassToEdge(kernel, k) +
         three * footprintMassToEdge(kernel, k - 1) - footprintMassToEdge(kernel, k - 2);
}

// ---- Narrow kernels: straight into the histogram ----
//
// Most contributions cover a few bins (a wall seen head-on: under one). For
// them the difference buffer would cost more than it saves (24 CDF values and
// a per-pixel integration), so a kernel whose support touches at most
// FOOTPRINT_DIRECT_BINS bins adds its bin masses F(k + 1) - F(k) to the float
// histogram directly; wider ones go to the difference buffer. Which way a
// contribution goes depends on it alone, so the bytes stay deterministic. A
// spike or a kernel inside one bin adds exactly its value to point sampling's
// bin (mass 1.0).
const int FOOTPRINT_DIRECT_BINS = 4;

// First and last bin the kernel's support [knot 0, knot 3] touches, each
// clamped to [-1, bins] (-1: before the axis, bins: after it).
TOFSIM_PHYSICS_FN ivec2 footprintSupport(vec3 kernel, int bins) {
  double lo = clamp(floor(footprintKnot(kernel, 0)), double(-1.0f), double(bins));
  double hi = clamp(floor(footprintKnot(kernel, 3)), double(-1.0f), double(bins));
  return ivec2(int(lo), int(hi));
}

// Whether the kernel is deposited straight into the histogram.
TOFSIM_PHYSICS_FN bool footprintIsNarrow(ivec2 support) {
  return support.y - support.x < FOOTPRINT_DIRECT_BINS;
}

// Mass of the kernel in bin k (exact CDF difference), rounded to float: the
// factor of the contribution's value added to bin k.
TOFSIM_PHYSICS_FN float footprintBinMass(vec3 kernel, int k) {
  return float(footprintCdf(kernel, double(k + 1)) - footprintCdf(kernel, double(k)));
}

#endif  // TOFSIM_FOOTPRINT_KERNEL_GLSL
