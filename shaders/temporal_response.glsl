// The temporal-response stage's per-bin arithmetic, written once in the
// common subset of GLSL 4.50 and C++/GLM (the rules of transient_physics.glsl)
// so that the GL pass (response_integrate.comp) and the CPU's
// physics::applyResponse (TemporalResponse.h) give the same bytes. The design,
// its model and its tests: core/physics/temporal_response.md.
//
// A delayed response class holds, per pixel, the bin integrals x[n] of the
// light its contributions deposited (as a footprint difference buffer, summed
// twice). Its kernel is (1 - fraction) delta(t) + fraction k(t); the stage
// outputs, per bin n of the axis,
//
//   y[n] = prompt x[n] + sum_{j < L} tap[j] x[n - delay - j] + tail[n],
//   tail[n] = ratio tail[n - 1] + weight x[n - delay - L],
//
// an FIR of L taps from bin `delay` on followed by a geometric tail: an
// exponential is L = 1 and its tail, a Gaussian or a table L taps and no tail.
// The coefficients are the exact bin integrals of k convolved with the box of
// one bin (TemporalResponse.h: responseTaps), computed once per kernel in C++
// (GLSL has no double exp or erf) and handed to both backends. A class of
// several kernels runs one such stage per member, each on the previous one's
// output (a cascade); a kernel that re-emits passes its delayed share (fir +
// tail) through its matrix.
#ifndef TOFSIM_TEMPORAL_RESPONSE_GLSL
#define TOFSIM_TEMPORAL_RESPONSE_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

// The tail's state at bin n from its state at n - 1 and the light x[n -
// delay - L] that enters it (0 before the axis).
TOFSIM_PHYSICS_FN dvec3 responseTail(double ratio, double weight, dvec3 tail, dvec3 entering) {
  return ratio * tail + weight * entering;
}

// One FIR term added to the running sum, taps in increasing order.
TOFSIM_PHYSICS_FN dvec3 responseFirTerm(dvec3 sum, double tap, dvec3 x) { return sum + tap * x; }

// Bin n's output: the prompt share of its own light, the FIR's sum and the
// tail's state at n.
TOFSIM_PHYSICS_FN dvec3 responseOutput(double prompt, dvec3 x, dvec3 fir, dvec3 tail) {
  return prompt * x + fir + tail;
}

// Re-emission (fluorescence's Stokes shift): the light absorbed in channel j
// comes back as column j of m. Written out column by column, in this order,
// so both compilers round the same way (no matrix product of their own).
TOFSIM_PHYSICS_FN dvec3 responseReemit(dmat3 m, dvec3 v) {
  return m[0] * v.x + m[1] * v.y + m[2] * v.z;
}

// Bin n's output for a kernel that re-emits: its delayed share (the FIR and
// the tail) through m, the prompt share as it came. Only for m != identity:
// responseOutput's sum is rounded in another order.
TOFSIM_PHYSICS_FN dvec3 responseReemittedOutput(double prompt, dvec3 x, dvec3 fir, dvec3 tail,
                                                dmat3 m) {
  return prompt * x + responseReemit(m, fir + tail);
}

// The light a stage that re-emits gives out on an endless axis for input
// light e (per channel): its prompt share as it came, the delayed share (1 -
// prompt: the taps' sum) through m. What the stage's output lacks of it on
// the axis is past the last bin; the rest of the input was absorbed.
TOFSIM_PHYSICS_FN dvec3 responseExpected(double prompt, dmat3 m, dvec3 e) {
  return prompt * e + responseReemit(m, (1.0 - prompt) * e);
}

#endif  // TOFSIM_TEMPORAL_RESPONSE_GLSL
