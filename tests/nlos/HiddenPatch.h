#pragma once
// The confocal hidden-patch scene of the NLOS tests and its closed form (the
// third bounce, ../shared/research/nlos-capture-format.md section 5), shared
// by the IR and the reference tests so both meet the same answer.

#include <cmath>
#include <cstddef>

#include "support/AnalyticScenes.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline::test {

constexpr float kWallAlbedo = 0.5f, kPatchAlbedo = 0.8f;
constexpr float kPatchDistance = 0.4f, kPatchSide = 0.2f;

// A 1 m wall at z = 0 facing +z ("quad0") and a square patch facing it at z = r.
inline scene::Scene hiddenPatch() {
  scene::Scene s;
  tofsim::test::addQuad(s, glm::vec3(0.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(kWallAlbedo));
  tofsim::test::addQuad(s, glm::vec3(0.0f, 0.0f, kPatchDistance), glm::vec3(0, 0, -1), kPatchSide,
                        glm::vec3(kPatchAlbedo));
  return s;
}

// A 3 x 3 scan of the wall, 1 cm bins from 0.5 m of optical path, IR with
// exact visibility and an RSM of rsm x rsm texels.
inline config::RunConfig nlosConfig(config::NlosScan scan, int rsm) {
  config::RunConfig c;
  config::NlosConfig n;
  n.relay_wall = "quad0";
  n.scan = scan;
  n.sensor_grid = {3, 3};
  // Off to the side and nearer the wall than the patch, so that no line of
  // sight to a wall point crosses the patch.
  n.sensor_origin = {-0.8f, 0.0f, 0.3f};
  n.laser_origin = {-0.8f, 0.1f, 0.3f};
  c.nlos = n;
  c.render.time.start_s = 0.5 / kSpeedOfLight_m_per_s;  // 0.5 m of optical path
  c.render.time.bin_width_s = 0.01 / kSpeedOfLight_m_per_s;
  c.render.time.bins = 150;
  c.render.pixel_footprint = false;
  c.render.indirect.rsm_resolution = rsm;
  c.render.indirect.visibility = capture::Visibility::Exact;
  c.render.indirect.geometry_term_clamp_per_m2 = 0.0f;
  c.render.indirect.vpl_footprint = false;
  c.cpu_threads = 2;
  return c;
}

inline NlosVolume render(const config::RunConfig& c, const scene::Scene& s) {
  return renderNlosScan(c, s, planNlosScan(c, s));
}

// The closed form over the patch, cut into m x m elements: energy (summed
// over the bins and R, G, B) and energy-weighted mean optical path at
// confocal point s, for the collimated laser of 1 W per channel.
struct Expected {
  double energy = 0.0, meanPath_m = 0.0;
};
inline Expected closedForm(const glm::vec3& s) {
  const int m = 400;
  const double h = kPatchSide / m;
  const double rho = double(kWallAlbedo) * kPatchAlbedo * kWallAlbedo / (M_PI * M_PI * M_PI);
  Expected e;
  double weighted = 0.0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const glm::dvec3 x(-kPatchSide / 2 + (i + 0.5) * h, -kPatchSide / 2 + (j + 0.5) * h,
                         kPatchDistance);
      const glm::dvec3 d = x - glm::dvec3(s);
      const double r = glm::length(d);
      const double c = d.z / r;  // every cosine: wall (+z) and patch (-z) normals
      const double w = 3.0 * rho * std::pow(c, 4) / std::pow(r, 4) * h * h;
      e.energy += w;
      weighted += w * 2.0 * r;
    }
  }
  e.meanPath_m = weighted / e.energy;
  return e;
}

// Energy and mean optical path of one point's histogram in H.
struct Measured {
  double energy = 0.0, meanPath_m = 0.0;
};
inline Measured measured(const NlosVolume& v, std::size_t point) {
  const std::size_t points = v.H.size() / v.axis.bins;
  Measured m;
  double weighted = 0.0;
  for (int32_t t = 0; t < v.axis.bins; ++t) {
    const double h = v.H[t * points + point];
    m.energy += h;
    weighted += h * (v.axis.start_m() + (t + 0.5) * v.axis.bin_width_m());
  }
  m.meanPath_m = weighted / m.energy;
  return m;
}

}  // namespace tofsim::pipeline::test
