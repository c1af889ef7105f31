#pragma once
// The homogeneous participating medium that fills the scene (issue 42: fog,
// smoke, turbid water): what absorbs and scatters light on every leg of a
// path. Its index of refraction is the time axis's (TimeAxis::
// index_of_refraction: light covers c / eta metres per second), so a path's
// geometric length in the medium is its optical path / eta.
//
// A medium that fills the scene attenuates a path by exp(-sigma_t x) over its
// whole geometric length x, leg by leg (light -> vertex, vertex -> vertex,
// vertex -> camera): physics::mediumTransmittance (shaders/medium.glsl).

#include <cstdint>
#include <glm/glm.hpp>

namespace tofsim::capture {

struct Medium {
  /// Absorption and scattering coefficients per channel (R, G, B), 1/m, >= 0.
  glm::vec3 sigma_a_per_m{0.0f};
  glm::vec3 sigma_s_per_m{0.0f};
  /// The phase function: physics::PHASE_ISOTROPIC, PHASE_HENYEY_GREENSTEIN
  /// (asymmetry g in (-1, 1)) or PHASE_RAYLEIGH (shaders/medium.glsl).
  int32_t phase = 0;
  float g = 0.0f;

  /// Whether there is a medium at all: without one every renderer does
  /// exactly what it did before (same bytes).
  bool present() const {
    return glm::any(glm::greaterThan(sigma_a_per_m + sigma_s_per_m, glm::vec3(0.0f)));
  }
  /// Whether it scatters (sigma_s > 0 in a channel): only then do the
  /// light's paths leave medium VPLs (ir/MediumVpls.h); an absorbing-only
  /// medium only attenuates.
  bool scatters() const { return glm::any(glm::greaterThan(sigma_s_per_m, glm::vec3(0.0f))); }
  /// Extinction, sigma_a + sigma_s, 1/m.
  glm::vec3 sigmaT() const { return sigma_a_per_m + sigma_s_per_m; }
  /// Single-scattering albedo sigma_s / sigma_t per channel (0 where sigma_t is 0).
  glm::vec3 albedo() const {
    const glm::vec3 t = sigmaT();
    return glm::vec3(t.x > 0.0f ? sigma_s_per_m.x / t.x : 0.0f,
                     t.y > 0.0f ? sigma_s_per_m.y / t.y : 0.0f,
                     t.z > 0.0f ? sigma_s_per_m.z / t.z : 0.0f);
  }
};

}  // namespace tofsim::capture
