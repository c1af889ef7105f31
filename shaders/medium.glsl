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

#endif  // TOFSIM_MEDIUM_GLSL
