#pragma once
// CpuBackend::DirectConstants: what the light, the time axis and the job fix
// for the direct gather (CpuDirectGather.cpp) and the medium's single
// scattering (CpuMediumDirect.cpp), which adds only the medium's own terms.

#include <glm/glm.hpp>

#include "tofsim/capture/Light.h"
#include "tofsim/cpu/CpuBackend.h"

namespace tofsim::cpu {

/// What the light, the time axis and the job fix for every direct sample of
/// a tile, read once per tile.
struct CpuBackend::DirectConstants {
  capture::Light::ProfileTerms profile;  ///< the light's (Light::profileTerms)
  glm::vec3 light_world{0.0f};           ///< the light's position, m
  glm::vec3 intensity_W_per_sr{0.0f};
  float start_m = 0.0f;  ///< of the time axis, as optical path
  float width_m = 1.0f;  ///< of a bin, as optical path
  float eta = 1.0f;      ///< index of refraction
  int bins = 0;
  bool footprint = false;  ///< render.pixel_footprint
  bool delayed = false;    ///< the render has delayed response classes
  bool medium = false;     ///< a medium fills the scene (Medium::present)
  glm::vec3 sigmaT{0.0f};  ///< its extinction, 1/m
};

}  // namespace tofsim::cpu
