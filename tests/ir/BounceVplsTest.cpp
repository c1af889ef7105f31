// The VPLs of later bounces (ir::traceBounce, withLaterBounces) against what
// light transport fixes exactly: in a closed box of albedo rho every ray hits,
// so a bounce carries exactly rho times the power of the one before; each
// parent's colour keeps its share; the path grows by eta times the leg; rays
// that leave the scene make no VPL; the same seed gives the same bytes, on
// any number of threads; Russian roulette keeps each bounce's power (mean
// over seeds) with fewer VPLs.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "support/AnalyticScenes.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::ir {
namespace {

Vpl vplAt(const glm::vec3& p, const glm::vec3& n, const glm::vec3& flux, float path_m) {
  return Vpl{glm::vec4(p, path_m), glm::vec4(n, 0.0f), glm::vec4(flux, 0.0f)};
}

glm::dvec3 totalFlux(const std::vector<Vpl>& vpls) {
  glm::dvec3 sum(0.0);
  for (const Vpl& v : vpls) sum += glm::dvec3(glm::vec3(v.flux));
  return sum;
}

TEST(BounceVplsTest, ClosedBoxBounceCarriesAlbedoTimesTheParentsPowerInTheirColours) {
  const float rho = 0.6f;
  const scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(rho));
  const rays::RayScene scene(box, 1);
  // A red parent of power 1 on the floor and a blue one of power 3 on a wall:
  // systematic resampling gives them 1/4 and 3/4 of the children (+-1).
  const std::vector<Vpl> parents = {vplAt({0.2f, -1.0f, 0.1f}, {0, 1, 0}, {1, 0, 0}, 2.0f),
                                    vplAt({1.0f, 0.3f, -0.4f}, {-1, 0, 0}, {0, 0, 3}, 1.5f)};
  const std::size_t count = 4000;
  const std::vector<Vpl> children = traceBounce(scene, parents, count, 2, 7, 1.0);
  ASSERT_EQ(children.size(), count);  // closed: no ray escapes
  const glm::dvec3 sum = totalFlux(children);
  EXPECT_NEAR(sum.r, rho * 1.0, rho * 1.0 / 1000.0);  // one child of 1000 either way
  EXPECT_NEAR(sum.b, rho * 3.0, rho * 3.0 / 3000.0);
  EXPECT_EQ(sum.g, 0.0);
  EXPECT_NEAR(sum.r + sum.b, rho * 4.0, 1e-5);  // each child carries rho * total / count
  for (const Vpl& c : children) {
    const glm::vec3 p(c.positionPath);
    EXPECT_NEAR(glm::length(glm::vec3(c.normal)), 1.0f, 1e-5f);
    EXPECT_EQ(c.patchU, glm::vec4(0.0f));  // a point VPL: no RSM patch
    EXPECT_EQ(c.patchV, glm::vec4(0.0f));
    // The normal faces into the box, towards where the light came from.
    EXPECT_GT(glm::dot(glm::vec3(c.normal), -p), 0.0f);
  }
}

TEST(BounceVplsTest, PathGrowsByEtaTimesTheLegFromTheParent) {
  const scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(0.5f));
  const rays::RayScene scene(box, 1);
  const glm::vec3 p(0.0f, -1.0f, 0.0f);
  const std::vector<Vpl> parents = {vplAt(p, {0, 1, 0}, glm::vec3(1.0f), 3.0f)};
  const double eta = 1.33;
  const std::vector<Vpl> children = traceBounce(scene, parents, 500, 2, 1, eta);
  ASSERT_EQ(children.size(), 500u);
  double meanCos = 0.0;
  for (const Vpl& c : children) {
    const glm::vec3 leg = glm::vec3(c.positionPath) - p;
    EXPECT_NEAR(c.positionPath.w, 3.0 + eta * glm::length(leg), 1e-5);
    meanCos += glm::normalize(leg).y / 500.0;
    // On a face of the box, above the parent's floor.
    const glm::vec3 q(c.positionPath);
    EXPECT_NEAR(std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}), 1.0f, 1e-5f);
    EXPECT_GT(q.y, -1.0f + 1e-4f);
  }
  // Cosine-weighted directions: E[cos theta] = 2/3 (500 samples: sd 0.011).
  EXPECT_NEAR(meanCos, 2.0 / 3.0, 0.04);
}

TEST(BounceVplsTest, RaysThatLeaveTheSceneMakeNoVpl) {
  const scene::Scene plane = test::makePlane(2.0f);
  const rays::RayScene scene(plane, 1);
  // On the only surface, shooting away from it: every ray escapes.
  const std::vector<Vpl> parents = {vplAt({0, 0, 0}, {0, 0, 1}, glm::vec3(1.0f), 1.0f)};
  EXPECT_TRUE(traceBounce(scene, parents, 100, 2, 1, 1.0).empty());
}

TEST(BounceVplsTest, LaterBouncesFollowTheFirstAndAreDeterministic) {
  const scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(0.5f));
  capture::RenderJob job;
  job.scene = &box;
  job.settings.indirect.bounces = 4;
  job.settings.indirect.vpls_per_bounce = 300;
  const std::vector<Vpl> first = {vplAt({0.2f, -1.0f, 0.1f}, {0, 1, 0}, glm::vec3(1.0f), 2.0f)};
  const BouncedVpls a = withLaterBounces(job, first);
  ASSERT_EQ(a.bounces(), 4);
  EXPECT_EQ(a.countOf(1), 1u);
  for (int32_t k = 2; k <= 4; ++k) EXPECT_EQ(a.countOf(k), 300u);
  EXPECT_EQ(std::memcmp(&a.vpls[0], &first[0], sizeof(Vpl)), 0);  // bounce 1 unchanged, first
  // Each bounce halves the power (albedo 0.5) exactly.
  for (int32_t k = 2; k <= 4; ++k) {
    const std::vector<Vpl> bounce(a.vpls.begin() + a.firstOfBounce[k - 1],
                                  a.vpls.begin() + a.firstOfBounce[k]);
    EXPECT_NEAR(totalFlux(bounce).g, std::pow(0.5, k - 1), 1e-6);
  }
  const BouncedVpls b = withLaterBounces(job, first);
  ASSERT_EQ(a.vpls.size(), b.vpls.size());
  EXPECT_EQ(std::memcmp(a.vpls.data(), b.vpls.data(), a.vpls.size() * sizeof(Vpl)), 0);
  job.settings.seed = 2;
  const BouncedVpls c = withLaterBounces(job, first);
  EXPECT_NE(std::memcmp(a.vpls.data(), c.vpls.data(), a.vpls.size() * sizeof(Vpl)), 0);
  // bounces: 1 leaves the first bounce alone.
  job.settings.indirect.bounces = 1;
  const BouncedVpls one = withLaterBounces(job, first);
  EXPECT_EQ(one.vpls.size(), 1u);
  EXPECT_EQ(one.bounces(), 1);
}

TEST(BounceVplsTest, BytesDoNotDependOnTheThreads) {
  const scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(0.5f));
  capture::RenderJob job;
  job.scene = &box;
  job.settings.indirect.bounces = 3;
  job.settings.indirect.vpls_per_bounce = 1000;  // 4 runs of 256 rays, the last short
  const std::vector<Vpl> first = {vplAt({0.2f, -1.0f, 0.1f}, {0, 1, 0}, glm::vec3(1.0f), 2.0f),
                                  vplAt({1.0f, 0.3f, -0.4f}, {-1, 0, 0}, {0, 0, 3}, 1.5f)};
  for (const bool roulette : {false, true}) {
    job.settings.indirect.russian_roulette = roulette;
    job.settings.indirect.trace_threads = 1;
    const BouncedVpls one = withLaterBounces(job, first);
    for (const int32_t threads : {2, 3, 0}) {
      job.settings.indirect.trace_threads = threads;
      const BouncedVpls other = withLaterBounces(job, first);
      ASSERT_EQ(one.vpls.size(), other.vpls.size()) << threads;
      EXPECT_EQ(one.firstOfBounce, other.firstOfBounce);
      EXPECT_EQ(std::memcmp(one.vpls.data(), other.vpls.data(), one.vpls.size() * sizeof(Vpl)), 0)
          << threads << " threads, roulette " << roulette;
    }
  }
}

// Per bounce k = 2..4 and channel: the mean over seeds of the bounce's power,
// and the standard error of that mean.
struct BouncePower {
  double mean[3][3] = {}, stderr_[3][3] = {};
  double vpls = 0.0;  // mean VPLs of bounces 2..4
};

BouncePower powerOverSeeds(capture::RenderJob job, const std::vector<Vpl>& first, int seeds) {
  double sum[3][3] = {}, squares[3][3] = {};
  BouncePower out;
  for (int s = 0; s < seeds; ++s) {
    job.settings.seed = 100 + static_cast<uint64_t>(s);
    const BouncedVpls b = withLaterBounces(job, first);
    out.vpls += static_cast<double>(b.vpls.size() - first.size()) / seeds;
    for (int32_t k = 2; k <= 4; ++k) {
      const std::vector<Vpl> bounce(b.vpls.begin() + b.firstOfBounce[k - 1],
                                    b.vpls.begin() + b.firstOfBounce[k]);
      const glm::dvec3 p = totalFlux(bounce);
      for (int c = 0; c < 3; ++c) {
        sum[k - 2][c] += p[c];
        squares[k - 2][c] += p[c] * p[c];
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) {
      out.mean[k][c] = sum[k][c] / seeds;
      const double var =
          (squares[k][c] / seeds - out.mean[k][c] * out.mean[k][c]) * seeds / (seeds - 1.0);
      out.stderr_[k][c] = std::sqrt(std::max(0.0, var) / seeds);
    }
  }
  return out;
}

TEST(BounceVplsTest, RussianRouletteKeepsThePowerWithFewerVpls) {
  // Coloured walls (q = 0.8 on the floor, 0.9 on the walls, channels unlike)
  // and an open corner, so rays escape too.
  const scene::Scene corner =
      test::makeCorner(glm::vec3(0.8f, 0.3f, 0.2f), glm::vec3(0.2f, 0.5f, 0.9f));
  capture::RenderJob job;
  job.scene = &corner;
  job.settings.indirect.bounces = 4;
  job.settings.indirect.vpls_per_bounce = 2000;
  job.settings.indirect.trace_threads = 0;
  const std::vector<Vpl> first = {vplAt({0.3f, 0.0f, 0.3f}, {0, 1, 0}, glm::vec3(1.0f), 2.0f)};
  const int seeds = 40;
  const BouncePower plain = powerOverSeeds(job, first, seeds);
  job.settings.indirect.russian_roulette = true;
  const BouncePower rr = powerOverSeeds(job, first, seeds);
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) {
      // Unbiased: the means agree within 4 standard errors of their difference.
      const double se = std::hypot(plain.stderr_[k][c], rr.stderr_[k][c]);
      EXPECT_GT(plain.mean[k][c], 0.0);
      EXPECT_NEAR(rr.mean[k][c], plain.mean[k][c], 4.0 * se)
          << "bounce " << k + 2 << " channel " << c << ", se " << se;
      EXPECT_LT(se, 0.05 * plain.mean[k][c]);  // and the test can see a 20 % bias
    }
  }
  EXPECT_LT(rr.vpls, 0.7 * plain.vpls);
}

}  // namespace
}  // namespace tofsim::ir
