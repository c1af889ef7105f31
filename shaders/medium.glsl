// A homogeneous participating medium's physics (issue 42), written once for
// both backends under transient_physics.glsl's rules (plain functions of
// scalars and vec3, f-suffixed literals, TOFSIM_PHYSICS_FN); C++ includes it
// through core/physics/include/tofsim/physics/MediumPhysics.h. The medium
// itself is capture::Medium (sigma_a, sigma_s per channel, phase, g).
//
// Direction convention of the phase functions: cosTheta is the cosine of the
// scattering angle, between the direction the light travelled in and the one
// it leaves along: 1 is straight on (forward), -1 straight back. A vertex's
// scatter() gets wi toward where the light came from and wo toward where it
// goes, so cosTheta = dot(-wi, wo).
#ifndef TOFSIM_MEDIUM_GLSL
#define TOFSIM_MEDIUM_GLSL

#include "transient_physics.glsl"

const int PHASE_ISOTROPIC = 0;
const int PHASE_HENYEY_GREENSTEIN = 1;
const int PHASE_RAYLEIGH = 2;

// Henyey-Greenstein: (1 - g^2) / (4 pi (1 + g^2 - 2 g cosTheta)^1.5), 1/sr.
TOFSIM_PHYSICS_FN float phaseHenyeyGreenstein(float g, float cosTheta) {
  float denom = 1.0f + g * g - 2.0f * g * cosTheta;
  return (1.0f - g * g) / (4.0f * PI * denom * sqrt(denom));
}

// Rayleigh: 3 (1 + cosTheta^2) / (16 pi), 1/sr.
TOFSIM_PHYSICS_FN float phaseRayleigh(float cosTheta) {
  return 3.0f * (1.0f + cosTheta * cosTheta) / (16.0f * PI);
}

// The phase function of model PHASE_* (g only for Henyey-Greenstein), 1/sr;
// each integrates to 1 over the sphere.
TOFSIM_PHYSICS_FN float phaseFunction(int model, float g, float cosTheta) {
  if (model == PHASE_HENYEY_GREENSTEIN) return phaseHenyeyGreenstein(g, cosTheta);
  if (model == PHASE_RAYLEIGH) return phaseRayleigh(cosTheta);
  return 1.0f / (4.0f * PI);
}

// Fraction of the light per channel that crosses `distance` metres of the
// medium (geometric length, not optical path) without being absorbed or
// scattered away: exp(-sigma_t distance).
TOFSIM_PHYSICS_FN vec3 mediumTransmittance(vec3 sigmaT, float distance) {
  return exp(-sigmaT * distance);
}

// Phase sampling (the reference's medium vertices; IR's medium VPLs): the
// cosine of a scattering angle drawn from the phase function of model
// PHASE_* from one uniform number u in [0, 1), pdf = 2 pi phaseFunction(mu)
// over mu in [-1, 1]. Henyey-Greenstein by its inverse CDF (isotropic below
// |g| = 1e-3, where the closed form cancels); Rayleigh by the real root of
// its cubic CDF mu^3 + 3 mu = 8 u - 4 (Cardano: mu = A - 1/A with
// A = cbrt(z + sqrt(z^2 + 1)), z = 4 u - 2, taken on |z| and signed so that
// the sum never cancels).
TOFSIM_PHYSICS_FN float sampleHenyeyGreensteinCosine(float g, float u) {
  if (abs(g) < 1e-3f) return 1.0f - 2.0f * u;
  float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u);
  return clamp((1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
}

TOFSIM_PHYSICS_FN float sampleRayleighCosine(float u) {
  float z = 4.0f * u - 2.0f;
  float a = pow(abs(z) + sqrt(z * z + 1.0f), 1.0f / 3.0f);
  float mu = a - 1.0f / a;
  return clamp(z < 0.0f ? -mu : mu, -1.0f, 1.0f);
}

TOFSIM_PHYSICS_FN float samplePhaseCosine(int model, float g, float u) {
  if (model == PHASE_HENYEY_GREENSTEIN) return sampleHenyeyGreensteinCosine(g, u);
  if (model == PHASE_RAYLEIGH) return sampleRayleighCosine(u);
  return 1.0f - 2.0f * u;
}

// A direction leaving a medium point, drawn from the phase function about
// the unit direction the light (or, traced backwards, the path) travels in,
// `forward`: cos(angle to forward) from samplePhaseCosine(u1), azimuth
// 2 pi u2. Its pdf is phaseFunction(model, g, dot(forward, result)), 1/sr.
TOFSIM_PHYSICS_FN vec3 samplePhaseDirection(int model, float g, vec3 forward, float u1, float u2) {
  float mu = samplePhaseCosine(model, g, u1);
  float sinTheta = sqrt(max(0.0f, 1.0f - mu * mu));
  float phi = 2.0f * PI * u2;
  return basisAround(forward) * vec3(sinTheta * cos(phi), sinTheta * sin(phi), mu);
}

// ---------------------------------------------------------------------------
// Single scattering of the light along a camera ray (issue 42, item 3): the
// medium's direct light, the lidar equation's backscatter, per time bin.
// Both backends' medium passes (core/cpu/src/CpuMediumDirect.cpp,
// shaders/medium_direct.comp) walk the same bins and nodes with these
// functions; only the light's visibility test is theirs.
//
// The ray x(s) = o + s w (unit w) meets its first surface at s = D, or none.
// Light from l scatters once at x(s) toward the camera:
//   L = integral sigma_s p(cos) I profile(u) / r^2 exp(-sigma_t (r + s)) V ds,
// r = |x(s) - l|, u = (x(s) - l) / r the light's direction of travel, cos =
// dot(u, -w) (1: forward), V the light's visibility. Its optical path is
// eta (r + s + lensPath) (camera_unwarp: eta r), increasing in s (unwarped:
// decreasing up to the point closest to the light, increasing after it: two
// branches), so each time bin is an interval of s in closed form
// (mediumRayParameter). Each interval is integrated by Gauss-Legendre in the
// angle phi, s = s_c + h tan(phi), about the closest approach s_c at
// distance h from the light: ds / r^2 = dphi / h, so the 1/r^2 peak, which
// is all the integrand's steepness near the light, becomes flat. A ray
// through the light (h = 0: a camera co-located with the light) diverges
// there; the emitter's size bounds it: 1/r^2 is 1/(r^2 + R^2), R =
// MEDIUM_EMITTER_RADIUS_M (the factor differs from 1 by (R/r)^2: 1e-6 at 1 m).
// Each interval is cut into angle steps of at most MEDIUM_MAX_ANGLE_STEP.
// Measured against dense double-precision integrals of the same formula
// (tests/render/MediumDirectGLTest.cpp's cases): 2.5e-6 relative per bin on
// the lidar equation, 1e-5 on a ray passing 12 cm from the light, 7e-5 at
// 3 cm, 2e-4 at 1 cm (float rounding of the bins' ends); a spot's rim and a
// shadow's edge are steps the nodes resolve to their spacing.

// The emitter's radius: the light is a ball of this size for the medium's
// 1/r^2 (it bounds the integral of a ray through the light), metres.
const float MEDIUM_EMITTER_RADIUS_M = 1e-3f;
// Gauss-Legendre nodes per angle step, and the largest angle step: a forward
// Henyey-Greenstein lobe (g = 0.9) is ~0.1 rad wide in phi.
const int MEDIUM_GAUSS_NODES = 4;
const float MEDIUM_MAX_ANGLE_STEP = PI / 64.0f;
// A span of the ray with no end (the ray sees no surface), as its s1.
const float MEDIUM_UNBOUNDED = -1.0f;
// Angle steps at least of a span to infinity (one per ray that misses, off
// the axis): its transmittance falls as exp(-c / (pi/2 - phi)), which one
// step's nodes follow to ~1e-3 only.
const int MEDIUM_TAIL_STEPS = 16;
// The ray's branches of monotonic path: light -> x -> camera (increasing);
// with the camera leg untimed, light -> x before the closest approach
// (decreasing) and after it (increasing).
const int MEDIUM_BRANCH_CAMERA = 0;
const int MEDIUM_BRANCH_TOWARD_LIGHT = 1;
const int MEDIUM_BRANCH_FROM_LIGHT = 2;

// A camera ray as the integral needs it.
struct MediumRay {
  vec3 origin;      // o, where the camera leg ends
  vec3 direction;   // w, unit
  vec3 perpendicular;  // from the light to the ray's closest point (length miss)
  float lightDistance;  // |o - l|
  float along;      // dot(w, o - l) = -s_c
  float miss;       // h: the ray's distance from the light
  float height;     // sqrt(h^2 + R^2), the substitution's scale
  float surface;    // D, or MEDIUM_UNBOUNDED
  float lensPath;   // path added to the camera leg (a thin lens's), m; 0 unwarped
};

// The ray toward an emitter at `light` of radius `radius` (the light's
// MEDIUM_EMITTER_RADIUS_M, a VPL's mediumVplRadius).
TOFSIM_PHYSICS_FN MediumRay mediumEmitterRay(vec3 origin, vec3 direction, vec3 light, float radius,
                                             float surface, float lensPath) {
  MediumRay ray;
  ray.origin = origin;
  ray.direction = direction;
  vec3 a = origin - light;
  ray.lightDistance = length(a);
  ray.along = dot(direction, a);
  ray.perpendicular = a - ray.along * direction;
  // Its length, not sqrt(|a|^2 - along^2): that cancels where the ray passes
  // close to the light far from the camera.
  ray.miss = length(ray.perpendicular);
  ray.height = sqrt(ray.miss * ray.miss + radius * radius);
  ray.surface = surface;
  ray.lensPath = lensPath;
  return ray;
}

// The ray toward the light source.
TOFSIM_PHYSICS_FN MediumRay mediumRay(vec3 origin, vec3 direction, vec3 light, float surface,
                                      float lensPath) {
  return mediumEmitterRay(origin, direction, light, MEDIUM_EMITTER_RADIUS_M, surface, lensPath);
}

// A VPL as the emitter of the medium's light along a camera ray (issue 42,
// item 4; core/physics/medium_vpl_scattering.md): a point whose 1/r^2 the
// gathers bound by render.indirect's geometry clamp C (min(cos / d^2, C) at
// a medium receiver, whose cosine is 1). The quadrature's 1/(r^2 + R^2)
// bounds it the same way at r = 0 with R = 1 / sqrt(C), and is 1/r^2 to
// (R/r)^2 beyond; without a clamp (C <= 0) the VPL is as small as the light.
TOFSIM_PHYSICS_FN float mediumVplRadius(float clampPerM2) {
  return clampPerM2 > 0.0f ? 1.0f / sqrt(clampPerM2) : MEDIUM_EMITTER_RADIUS_M;
}

// The first and last branch of a ray (MEDIUM_BRANCH_*): unwarped, two.
TOFSIM_PHYSICS_FN ivec2 mediumBranches(bool unwarp) {
  return unwarp ? ivec2(MEDIUM_BRANCH_TOWARD_LIGHT, MEDIUM_BRANCH_FROM_LIGHT)
                : ivec2(MEDIUM_BRANCH_CAMERA, MEDIUM_BRANCH_CAMERA);
}

// The geometric path (without the lens's) at ray parameter s.
TOFSIM_PHYSICS_FN float mediumPathAt(MediumRay ray, int branch, float s) {
  float d = s + ray.along;
  float r = sqrt(ray.miss * ray.miss + d * d);
  return branch == MEDIUM_BRANCH_CAMERA ? r + s : r;
}

// The ray parameter where branch `branch` reaches geometric path q (clamped
// to where the branch starts or ends when q is outside it): r + s = q gives
// s = (q^2 - |o - l|^2) / (2 (q + w.(o - l))); r = q gives s_c -+ sqrt(q^2 - h^2).
TOFSIM_PHYSICS_FN float mediumRayParameter(MediumRay ray, int branch, float q) {
  if (branch == MEDIUM_BRANCH_CAMERA) {
    float d = q - ray.lightDistance;
    if (d <= 0.0f) return 0.0f;
    return d * (q + ray.lightDistance) / (2.0f * (q + ray.along));
  }
  float offset = sqrt(max(q * q - ray.miss * ray.miss, 0.0f));
  return branch == MEDIUM_BRANCH_TOWARD_LIGHT ? -ray.along - offset : -ray.along + offset;
}

// The branch's span of s, in front of the camera and before the surface:
// (s0, s1), s1 MEDIUM_UNBOUNDED without a surface; empty when s1 <= s0.
TOFSIM_PHYSICS_FN vec2 mediumSpan(MediumRay ray, int branch) {
  float closest = -ray.along;
  if (branch == MEDIUM_BRANCH_CAMERA) return vec2(0.0f, ray.surface);
  if (branch == MEDIUM_BRANCH_TOWARD_LIGHT) {
    float end = ray.surface < 0.0f ? closest : min(ray.surface, closest);
    return vec2(0.0f, max(end, 0.0f));
  }
  return vec2(max(closest, 0.0f), ray.surface);
}

TOFSIM_PHYSICS_FN bool mediumSpanEmpty(vec2 span) { return span.y >= 0.0f && span.y <= span.x; }

// The time bin of geometric path q on a ray, -1 before the axis and `bins`
// after it (no further).
TOFSIM_PHYSICS_FN int mediumBinOf(MediumRay ray, float q, float eta, float start_m,
                                  float binWidth_m, int bins) {
  float k = floor((eta * (q + ray.lensPath) - start_m) / binWidth_m);
  return int(clamp(k, -1.0f, float(bins)));
}

// The bins a branch's span crosses, from its start s0 to its end: (first,
// last), -1 standing for all the light before the axis and `bins` for all
// after it; last < first on a decreasing branch.
TOFSIM_PHYSICS_FN ivec2 mediumBinRange(MediumRay ray, int branch, vec2 span, float eta,
                                       float start_m, float binWidth_m, int bins) {
  int first = mediumBinOf(ray, mediumPathAt(ray, branch, span.x), eta, start_m, binWidth_m, bins);
  int last = span.y < 0.0f ? bins
                           : mediumBinOf(ray, mediumPathAt(ray, branch, span.y), eta, start_m,
                                         binWidth_m, bins);
  return ivec2(first, last);
}

// The part of the span whose light lands in bin k (-1: before the axis,
// `bins`: after it), in s.
TOFSIM_PHYSICS_FN vec2 mediumBinSpan(MediumRay ray, int branch, vec2 span, int k, float eta,
                                     float start_m, float binWidth_m, int bins) {
  vec2 part = span;
  bool increasing = branch != MEDIUM_BRANCH_TOWARD_LIGHT;
  if (k >= 0) {  // from the bin's lower edge on
    float s = mediumRayParameter(ray, branch, (start_m + float(k) * binWidth_m) / eta - ray.lensPath);
    if (increasing) {
      part.x = max(part.x, s);
    } else {
      part.y = min(part.y, s);
    }
  }
  if (k < bins) {  // up to its upper edge
    float s =
        mediumRayParameter(ray, branch, (start_m + float(k + 1) * binWidth_m) / eta - ray.lensPath);
    if (!increasing) {
      part.x = max(part.x, s);
    } else {
      part.y = part.y < 0.0f ? s : min(part.y, s);
    }
  }
  return part;
}

// An interval of s in the substitution's angle: the tangent where it starts,
// its width (phi1 - phi0, computed without the cancellation of two angles
// near pi/2) and its angle steps of `nodes` Gauss-Legendre nodes each
// (MEDIUM_GAUSS_NODES; a VPL's sampled span: mediumSampledInterval).
struct MediumInterval {
  float tan0;
  float width;
  int steps;
  int nodes;
};

TOFSIM_PHYSICS_FN MediumInterval mediumInterval(MediumRay ray, vec2 part) {
  MediumInterval iv;
  iv.tan0 = (part.x + ray.along) / ray.height;
  float width;
  if (part.y < 0.0f) {  // to infinity: phi1 = pi/2
    width = iv.tan0 > 0.0f ? atan(1.0f / iv.tan0) : 0.5f * PI - atan(iv.tan0);
  } else {
    float tan1 = (part.y + ray.along) / ray.height;
    float den = 1.0f + iv.tan0 * tan1;
    width = den > 0.0f ? atan((tan1 - iv.tan0) / den) : atan(tan1) - atan(iv.tan0);
  }
  iv.width = max(width, 0.0f);
  iv.steps = int(ceil(iv.width / MEDIUM_MAX_ANGLE_STEP));
  if (part.y < 0.0f && iv.width > 0.0f) iv.steps = max(iv.steps, MEDIUM_TAIL_STEPS);
  iv.nodes = MEDIUM_GAUSS_NODES;
  return iv;
}

// Node j of the n-node Gauss-Legendre rule on [0, 1] (n = 1, 2 or 4):
// (position, weight).
TOFSIM_PHYSICS_FN vec2 mediumGaussNode(int n, int j) {
  if (n == 1) return vec2(0.5f, 1.0f);
  if (n == 2) return vec2(j == 0 ? 0.2113248654051871f : 0.7886751345948129f, 0.5f);
  if (j == 0) return vec2(0.0694318442029737f, 0.1739274225687269f);
  if (j == 1) return vec2(0.3300094782075719f, 0.3260725774312731f);
  if (j == 2) return vec2(0.6699905217924281f, 0.3260725774312731f);
  return vec2(0.9305681557970263f, 0.1739274225687269f);
}

// One quadrature node: where it is, what the light does there, and its
// weight dphi / h (the measure ds / r^2 of the bounded 1/r^2).
struct MediumNode {
  vec3 x;          // the scattering point
  vec3 fromLight;  // u: unit, the light's direction of travel to x
  float s;         // ray parameter (camera leg), m
  float r;         // distance from the light, m
  float cosTheta;  // scattering angle's cosine toward the camera, dot(u, -w)
  float weight;    // 0: a node at s = infinity (nothing arrives)
};

// The node of angle step `step` of interval iv at gauss = (position in the
// step, 0 .. 1; weight in the step: a Gauss-Legendre node's, or 1 for a
// sample).
TOFSIM_PHYSICS_FN MediumNode mediumNodeAt(MediumRay ray, MediumInterval iv, int step,
                                          vec2 gauss) {
  MediumNode n;
  float stepWidth = iv.width / float(iv.steps);
  // tan(phi0 + offset) by the addition formula: precise where phi0 is near
  // +-pi/2, where phi0 itself has lost the digits s needs. It holds for
  // every offset (den < 0 past an offset of pi/2 from a negative phi0); den
  // is 0 only at phi = pi/2, s = infinity.
  float tau = tan((float(step) + gauss.x) * stepWidth);
  float den = 1.0f - iv.tan0 * tau;
  float t = den != 0.0f ? (iv.tan0 + tau) / den : 0.0f;
  // s - s_c; bounded so that d^2 stays finite toward s = infinity (where the
  // transmittance is 0, and exp(-0 x inf) of a channel without extinction
  // would be NaN).
  float d = min(t * ray.height, 1e18f);
  n.s = d - ray.along;
  n.r = max(sqrt(ray.miss * ray.miss + d * d), 1e-30f);
  n.x = ray.origin + n.s * ray.direction;
  n.fromLight = (ray.perpendicular + d * ray.direction) / n.r;
  n.cosTheta = clamp(-d / n.r, -1.0f, 1.0f);
  n.weight = den != 0.0f ? gauss.y * stepWidth / ray.height : 0.0f;
  return n;
}

// Node k of interval iv, k in [0, steps x nodes).
TOFSIM_PHYSICS_FN MediumNode mediumNode(MediumRay ray, MediumInterval iv, int k) {
  int step = k / iv.nodes;
  return mediumNodeAt(ray, iv, step, mediumGaussNode(iv.nodes, k - step * iv.nodes));
}

// A VPL's light along a camera ray, sampled (issue 42, item 4;
// medium_vpl_scattering.md, "Sampled"): the pass's cost was a quadrature
// node per bin per (ray, VPL) pair. Instead a pair is kept with probability
// q = min(1, e / threshold), e = mediumRayVplEstimate (the VPL's importance
// times the integral of its bounded 1/(r^2 + R^2) over the ray, width /
// height: what the pair can bring, within its transmittance and phase), and
// weighed 1 / q; a kept pair's integral is estimated by
// MEDIUM_VPL_RAY_SAMPLES points of the substitution's angle, one in each of
// as many equal steps, all at the same offset in their step (one uniform
// draw: systematic sampling), each deposited in the bin of its own path.
// Both are unbiased: the expected light of every bin is the integral's.
const int MEDIUM_VPL_RAY_SAMPLES = 2;
// The threshold keeps about MEDIUM_VPL_RAY_PAIRS pairs a ray where the
// VPLs' estimates sum as they would at the scene's scale
// (ir::mediumRayThreshold); fewer VPLs than that are all kept.
const float MEDIUM_VPL_RAY_PAIRS = 4096.0f;

// A VPL's importance for the roulette: its mean flux, a medium VPL's over
// 4 pi (an isotropic phase's intensity per unit flux; a surface VPL's flux is
// its cosine emitter's peak). Only the roulette's variance depends on it.
TOFSIM_PHYSICS_FN float mediumRayVplImportance(vec3 flux, vec3 normal) {
  float mean = (flux.x + flux.y + flux.z) / 3.0f;
  return normal == vec3(0.0f) ? mean / (4.0f * PI) : mean;
}

// What a (ray, VPL) pair can bring, for the roulette: the importance times
// the angle the ray's span (camera to surface) subtends, over the height.
TOFSIM_PHYSICS_FN float mediumRayVplEstimate(MediumRay ray, float importance) {
  return importance * mediumInterval(ray, vec2(0.0f, ray.surface)).width / ray.height;
}

// The pair's probability of being kept.
TOFSIM_PHYSICS_FN float mediumRayVplSurvival(float estimate, float threshold) {
  return threshold > 0.0f ? min(estimate / threshold, 1.0f) : 1.0f;
}

// The sampled interval of a branch's whole span: MEDIUM_VPL_RAY_SAMPLES
// steps of one node, mediumNodeAt(ray, iv, j, vec2(offset, 1)).
TOFSIM_PHYSICS_FN MediumInterval mediumSampledInterval(MediumRay ray, vec2 span) {
  MediumInterval iv = mediumInterval(ray, span);
  iv.steps = MEDIUM_VPL_RAY_SAMPLES;
  iv.nodes = 1;
  return iv;
}

// A node's radiance toward the camera, its weight included, before the
// light's visibility: sigma_s p(cos) I profile exp(-sigma_t (r + s)) dphi / h
// (the medium's sigma_s, sigma_t per channel, PHASE_* model and g; the
// light's intensity, W/sr, and its profile toward the node).
TOFSIM_PHYSICS_FN vec3 mediumNodeRadiance(MediumNode n, vec3 sigmaS, vec3 sigmaT, int phase,
                                          float g, vec3 intensity, float profile) {
  float scalar = n.weight * phaseFunction(phase, g, n.cosTheta) * profile;
  return sigmaS * intensity * mediumTransmittance(sigmaT, n.r + n.s) * scalar;
}

#endif  // TOFSIM_MEDIUM_GLSL
