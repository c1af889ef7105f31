// The homogeneous medium filling the scene (capture::Medium, issue 42) as
// the GL passes see it: a program compiled with MEDIUM (gpu::gatherDefines,
// only where RenderSettings::medium is present: every other render compiles
// the shaders of before) declares these uniforms, set by MediumUniforms.cpp
// (setMediumExtinction: uMediumSigmaT; setMediumScattering: the rest, for
// passes that scatter in the medium). The physics is medium.glsl's.
#ifndef TOFSIM_MEDIUM_UNIFORMS_GLSL
#define TOFSIM_MEDIUM_UNIFORMS_GLSL

#ifdef MEDIUM
#include "medium.glsl"

uniform vec3 uMediumSigmaT;  // extinction sigma_a + sigma_s per channel, 1/m
uniform vec3 uMediumSigmaS;  // scattering sigma_s per channel, 1/m
uniform int uMediumPhase;    // PHASE_* (medium.glsl)
uniform float uMediumG;      // Henyey-Greenstein's asymmetry

// The fraction of the light that crosses `distance` geometric metres of the
// medium (the legs of a path: light -> vertex, vertex -> vertex, vertex ->
// camera; a sum of legs is one call).
vec3 mediumLegsTransmittance(float distance) {
  return mediumTransmittance(uMediumSigmaT, distance);
}
#endif

#endif  // TOFSIM_MEDIUM_UNIFORMS_GLSL
