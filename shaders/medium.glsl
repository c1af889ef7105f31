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

#endif  // TOFSIM_MEDIUM_GLSL
