// The imperfect shadow map's verdicts against exact visibility, VPL-pixel
// pair by pair (issue 45, item 1), on the Cornell box protocol of
// bench/ism_bias/late_light.py (64 x 64 pixel centres, the 30-degree hard
// spot, RSM 32^2, the CPU backend's VPLs and maps). For every pair that would
// carry light (each on the other's lit side) an Embree occlusion ray says
// whether the VPL sees the pixel, as the exact visibility of the gather does;
// the ISM's map says it with two depth tolerances: the old one, one texel's
// depth at the paraboloid's centre (dist * texelAngle + 0.01 scene), and
// ismDepthBias, the one with the receiver's slope. Printed, per ISM setting
// (resolution, points per VPL, pull-push):
//  - "hid": the visible pairs the ISM calls hidden, as a share of the visible
//    pairs, and "hid light" as a share of their light (VPL flux times the
//    clamped cos cos / d^2);
//  - "leak": the hidden pairs the ISM calls visible, "leak light" that light
//    as a share of the visible pairs' light (so 1 - hid light + leak light is
//    ISM / exact for the one-bounce light);
//  - the hidden share of the light by path length, as the path past the
//    pixel's direct one (the windows of late_light.py: the direct peak, up to
//    400 ps = 12 cm after it, 400 ps - 1 ns, after 1 ns);
// then, for the default setting, both tolerances by path window and by
// distance from the VPL. Usage (bench/README.md, "The ISM's bias"):
//   tofsim_ism_pairs [side=64] [rsm=32] [threads=2]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "CpuIsm.h"
#include "support/BackendScene.h"
#include "support/TestJobs.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/ParallelFor.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;

/// A pair that would carry light: pixel sample and VPL on each other's lit side.
struct Pair {
  uint32_t pixel = 0, vpl = 0;
  float dist = 0.0f;       ///< VPL to pixel, m
  float excess = 0.0f;     ///< path past the pixel's direct path, m
  float light = 0.0f;      ///< VPL flux (R+G+B) times clamped cos cos / d^2
  float alpha_deg = 0.0f;  ///< between the pixel's normal and the direction to the VPL
  bool visible = false;    ///< exact: no occluder between them
};

constexpr std::array<float, 3> kPathEdges{0.12f, 0.30f, 0.60f};  // m past the direct path
constexpr std::array<const char*, 4> kPathNames{"peak..400 ps", "400 ps..1 ns", "1..2 ns",
                                                "> 2 ns"};
constexpr std::array<float, 3> kDistEdges{0.10f, 0.20f, 0.40f};  // m from the VPL
constexpr std::array<const char*, 4> kDistNames{"< 10 cm", "10-20 cm", "20-40 cm", "> 40 cm"};
constexpr std::array<float, 3> kAlphaEdges{35.0f, 60.0f, 80.0f};  // the receiver's angle, degrees
constexpr std::array<const char*, 4> kAlphaNames{"< 35 deg", "35-60 deg", "60-80 deg", "> 80 deg"};

template <std::size_t N>
int bucket(float x, const std::array<float, N>& edges) {
  return static_cast<int>(std::upper_bound(edges.begin(), edges.end(), x) - edges.begin());
}

/// Counts and light of one class of pairs, for the hidden / leak shares.
struct Tally {
  double visible = 0, hiddenPairs = 0, visibleLight = 0;
  double wrongHidden = 0, wrongHiddenLight = 0;  ///< visible, the ISM says hidden
  double leaked = 0, leakedLight = 0;            ///< hidden, the ISM says visible
  void add(const Pair& p, bool ismVisible) {
    if (p.visible) {
      visible += 1, visibleLight += p.light;
      if (!ismVisible) wrongHidden += 1, wrongHiddenLight += p.light;
    } else {
      hiddenPairs += 1;
      if (ismVisible) leaked += 1, leakedLight += p.light;
    }
  }
  double hid() const { return 100.0 * wrongHidden / std::max(visible, 1.0); }
  double hidLight() const { return 100.0 * wrongHiddenLight / std::max(visibleLight, 1e-30); }
  double leak() const { return 100.0 * leaked / std::max(hiddenPairs, 1.0); }
  double leakLight() const { return 100.0 * leakedLight / std::max(visibleLight, 1e-30); }
};

struct Setup {
  capture::RenderJob job;
  std::vector<ir::Vpl> vpls;
  std::vector<glm::vec3> x, n;  ///< pixel centres' surface points and normals
  std::vector<Pair> pairs;
  float sceneScale_m = 1.0f;
};

// The pairs of the protocol's render, each with its exact verdict.
void findPairs(Setup& s, const rays::RayScene& rays, int threads) {
  const glm::vec3 camera = s.job.camera().position_world, light = s.job.light.position_world;
  const float eps = 1e-4f * s.sceneScale_m;  // the exact gather's end offsets
  const float clamp = static_cast<float>(s.job.settings.indirect.geometry_term_clamp_per_m2);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const float direct = glm::length(s.x[i] - light) + glm::length(s.x[i] - camera);
    for (std::size_t k = 0; k < s.vpls.size(); ++k) {
      const ir::Vpl& v = s.vpls[k];
      const glm::vec3 p(v.positionPath), vn(v.normal);
      const glm::vec3 d = s.x[i] - p;
      const float dist = glm::length(d);
      if (dist < 1e-6f) continue;
      const float cosV = glm::dot(vn, d) / dist, cosX = -glm::dot(s.n[i], d) / dist;
      if (cosV <= 0.0f || cosX <= 0.0f) continue;
      Pair pair{static_cast<uint32_t>(i),
                static_cast<uint32_t>(k),
                dist,
                v.positionPath.w + dist + glm::length(s.x[i] - camera) - direct,
                (v.flux.x + v.flux.y + v.flux.z) * std::min(cosV * cosX / (dist * dist), clamp),
                glm::degrees(std::acos(std::min(cosX, 1.0f)))};
      s.pairs.push_back(pair);
    }
  }
  parallelFor(s.pairs.size(), threads, [&](std::size_t j) {
    Pair& p = s.pairs[j];
    const ir::Vpl& v = s.vpls[p.vpl];
    p.visible = !rays.occluded(glm::vec3(v.positionPath) + glm::vec3(v.normal) * eps,
                               s.x[p.pixel] + s.n[p.pixel] * eps);
  });
}

struct Verdicts {
  std::vector<uint8_t> oldBias, newBias;
};

// The ISM's verdict on each pair with the old tolerance and with
// ismDepthBias, from the finest level of the maps (after pull-push); the new
// one checked against CpuIsm::visible, the gather's recipe.
Verdicts ismVerdicts(const Setup& s, const capture::IndirectSettings& settings, int threads) {
  cpu::CpuIsm ism(*s.job.scene, s.vpls, settings, s.job.settings.seed);
  ism.allocate(s.vpls.size());
  ism.build(0, s.vpls.size(), threads);
  const int r = settings.ism_resolution;
  const float texelAngle = 4.0f / static_cast<float>(r), sceneBias = 0.01f * s.sceneScale_m;
  Verdicts out{std::vector<uint8_t>(s.pairs.size()), std::vector<uint8_t>(s.pairs.size())};
  std::vector<std::size_t> disagree(s.pairs.size(), 0);
  parallelFor(s.pairs.size(), threads, [&](std::size_t j) {
    const Pair& p = s.pairs[j];
    const ir::Vpl& v = s.vpls[p.vpl];
    const glm::vec3 d = (s.x[p.pixel] - glm::vec3(v.positionPath)) / p.dist;
    const glm::ivec2 t = physics::paraboloidTexelOf(glm::vec3(v.normal), d, r);
    const float stored = ism.map(p.vpl)[t.y * r + t.x];
    const float cosX = -glm::dot(s.n[p.pixel], d);
    out.oldBias[j] = p.dist - (p.dist * texelAngle + sceneBias) <= stored;
    out.newBias[j] = p.dist - physics::ismDepthBias(p.dist, cosX, texelAngle, sceneBias) <= stored;
    disagree[j] =
        out.newBias[j] != ism.visible(p.vpl, d, p.dist, s.n[p.pixel], 0.0f, s.sceneScale_m);
  });
  std::size_t n = 0;
  for (std::size_t c : disagree) n += c;
  if (n > 0) std::printf("  (%zu pairs where ismDepthBias here and CpuIsm::visible differ)\n", n);
  return out;
}

void printRow(const char* setting, const char* bias, const Setup& s,
              const std::vector<uint8_t>& verdict) {
  Tally all;
  std::array<Tally, 4> byPath;
  for (std::size_t j = 0; j < s.pairs.size(); ++j) {
    all.add(s.pairs[j], verdict[j] != 0);
    byPath[bucket(s.pairs[j].excess, kPathEdges)].add(s.pairs[j], verdict[j] != 0);
  }
  std::printf("| %s | %s | %.2f%% / %.2f%% | %.2f%% / %.2f%% | %.3f |", setting, bias, all.hid(),
              all.hidLight(), all.leak(), all.leakLight(),
              1.0 - all.hidLight() / 100.0 + all.leakLight() / 100.0);
  for (const Tally& t : byPath) std::printf(" %.1f%% / %.1f%% |", t.hidLight(), t.leakLight());
  std::printf("\n");
}

// Hidden and leaked light of one tolerance by path window (rows) and distance
// from the VPL (columns).
void printGrid(const char* title, const Setup& s, const std::vector<uint8_t>& verdict) {
  std::array<std::array<Tally, 4>, 4> grid;
  for (std::size_t j = 0; j < s.pairs.size(); ++j) {
    const Pair& p = s.pairs[j];
    grid[bucket(p.excess, kPathEdges)][bucket(p.dist, kDistEdges)].add(p, verdict[j] != 0);
  }
  std::printf(
      "\n%s: hidden light / leaked light (share of the visible pairs' light; visible "
      "pairs)\n\n| path past the direct one |",
      title);
  for (const char* d : kDistNames) std::printf(" %s |", d);
  std::printf("\n|---|---|---|---|---|\n");
  for (int a = 0; a < 4; ++a) {
    std::printf("| %s |", kPathNames[a]);
    for (int b = 0; b < 4; ++b) {
      const Tally& t = grid[a][b];
      std::printf(" %.1f%% / %.1f%% (%.0fk) |", t.hidLight(), t.leakLight(), t.visible / 1000.0);
    }
    std::printf("\n");
  }
}

// Hidden and leaked light by the receiver's angle alpha (the old tolerance
// covers its own surface's points up to about 35 degrees), both tolerances.
void printByAngle(const Setup& s, const Verdicts& v) {
  std::array<Tally, 4> old, slope;
  for (std::size_t j = 0; j < s.pairs.size(); ++j) {
    const int a = bucket(s.pairs[j].alpha_deg, kAlphaEdges);
    old[a].add(s.pairs[j], v.oldBias[j] != 0);
    slope[a].add(s.pairs[j], v.newBias[j] != 0);
  }
  std::printf(
      "\nISM 32^2, 2048 points, by the angle between the pixel's normal and the "
      "direction to the VPL: hidden light / leaked light, old tolerance -> slope\n\n"
      "| receiver's angle | visible pairs | old | slope |\n|---|---|---|---|\n");
  for (int a = 0; a < 4; ++a) {
    std::printf("| %s | %.0fk | %.1f%% / %.1f%% | %.1f%% / %.1f%% |\n", kAlphaNames[a],
                old[a].visible / 1000.0, old[a].hidLight(), old[a].leakLight(), slope[a].hidLight(),
                slope[a].leakLight());
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int side = bench::arg(argc, argv, 1, 64);
  const int rsm = bench::arg(argc, argv, 2, 32);
  const int threads = bench::arg(argc, argv, 3, 2);
  const scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  Setup s;
  s.job = test::cornellBoxJob(scene, side, 371, 0.006);
  s.job.light.cone_half_angle_deg = 30.0f;  // the protocol's hard spot
  s.job.settings.indirect.rsm_resolution = rsm;
  const scene::Bounds b = scene.bounds();
  s.sceneScale_m = std::max(glm::length(b.max - b.min), 1e-6f);  // as CpuBackend's
  cpu::CpuBackend backend(cpu::CpuBackendOptions{threads, true});
  const rays::RayScene rays(scene, 0);
  backend.setScene(scene, &rays);
  const ir::CentreSurfaces centres = backend.prepareSurfaces(s.job);
  s.vpls = backend.generateVpls(s.job);
  for (std::size_t i = 0; i * 4 < centres.positions.size(); ++i) {
    if (centres.positions[4 * i + 3] == 0.0f) continue;
    s.x.emplace_back(centres.positions[4 * i], centres.positions[4 * i + 1],
                     centres.positions[4 * i + 2]);
    s.n.emplace_back(centres.normals[4 * i], centres.normals[4 * i + 1],
                     centres.normals[4 * i + 2]);
  }
  findPairs(s, rays, threads);
  std::size_t visible = 0;
  for (const Pair& p : s.pairs) visible += p.visible;
  std::printf(
      "%dx%d pixel centres (%zu on surfaces), %zu VPLs (RSM %d^2): %zu pairs carry light, "
      "%zu visible\n\n",
      side, side, s.x.size(), s.vpls.size(), rsm, s.pairs.size(), visible);
  std::printf(
      "| ISM | tolerance | hid: pairs / light | leak: pairs / light | ISM / exact "
      "light |");
  for (const char* p : kPathNames) std::printf(" hid / leak light, %s |", p);
  std::printf("\n|---|---|---|---|---|---|---|---|---|\n");
  struct Variant {
    int resolution, points;
    bool pullPush;
  };
  const Variant variants[] = {{32, 1000, true}, {32, 2048, true},   {32, 4000, true},
                              {32, 8000, true}, {32, 2048, false},  {16, 512, true},
                              {64, 8192, true}, {128, 32768, true}, {128, 2000, true}};
  Verdicts defaults;
  for (const Variant& v : variants) {
    capture::IndirectSettings settings = s.job.settings.indirect;
    settings.ism_resolution = v.resolution;
    settings.points_per_vpl = v.points;
    settings.ism_pull_push = v.pullPush;
    Verdicts verdicts = ismVerdicts(s, settings, threads);
    const std::string name = std::to_string(v.resolution) + "^2, " + std::to_string(v.points) +
                             " points" + (v.pullPush ? "" : ", no pull-push");
    printRow(name.c_str(), "old", s, verdicts.oldBias);
    printRow(name.c_str(), "slope", s, verdicts.newBias);
    if (v.resolution == 32 && v.points == 2048 && v.pullPush) defaults = std::move(verdicts);
  }
  printByAngle(s, defaults);
  printGrid("ISM 32^2, 2048 points (the default), the old tolerance", s, defaults.oldBias);
  printGrid("ISM 32^2, 2048 points (the default), ismDepthBias (the slope)", s, defaults.newBias);
  return 0;
}
