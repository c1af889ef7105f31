// The temporal-response stage on GL (footprint_deposit.glsl's depositDelayed,
// response_integrate.comp, through render::PixelFootprint) gives the CPU's
// volume (physics::depositWide into a class's buffer, physics::applyResponse,
// as cpu::ResponseClasses runs them): three delayed classes of one kernel (an
// exponential lifetime, a Gaussian delay, a table) beside the instant one,
// spikes, narrow and wide kernels, some across the axis's end, and the light
// the kernels carry past it; then classes that are cascades of two and three
// kernels (the scratch region's ping-pong) and kernels that re-emit. The
// Gaussian's taps make the pass take several dispatches, so the running sums
// cross chunks. Equal bytes on llvmpipe; the bound leaves room for a GPU
// compiler that fuses multiply-adds.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "GpuContract.h"
#include "FootprintDepositSource.h"
#include "PixelFootprint.h"
#include "support/GlTestContext.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/gl/Program.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::render {
namespace {

constexpr int32_t kBins = 1500;
constexpr double kBin_s = 10e-12;
constexpr int kPerPixel = 4;  // contributions per pixel, in order

const char* const kGatherBuffers = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 20) readonly buffer Kernels { vec4 kernels[]; };   // xyz kernel, w class
layout(std430, binding = 21) readonly buffer Energies { vec4 energies[]; }; // rgb energy
layout(std430, binding = 22) buffer Volume { float volume[]; };
layout(std430, binding = TOFSIM_SSBO_OUTSIDE_AXIS) buffer Lost { float lost[]; };
uniform int uBins;
uniform vec3 uCameraPosition_world;
)";

// One invocation per pixel adds its contributions in order, each to its
// class's buffer.
const char* const kGather = R"(
void main() {
  uint p = gl_GlobalInvocationID.x;
  float before = 0.0;
  float after = 0.0;
  for (uint c = 0u; c < uint(CONTRIBUTIONS); ++c) {
    uint k = p * uint(CONTRIBUTIONS) + c;
    // Class 0 through the same call: its region is the instant buffer (the
    // gathers' depositContribution is FootprintDepositGLTest's; one deposit
    // here keeps llvmpipe's compile short).
    depositDelayed(p, uint(kernels[k].w), kernels[k].xyz, energies[k].rgb, before, after);
  }
  lost[2u * p] = before;
  lost[2u * p + 1u] = after;
}
)";

std::string gatherSource() {
  return test::footprintDepositSource(kPerPixel, "#define RESPONSE_CLASSES\n", kGatherBuffers,
                                      kGather);
}

std::vector<physics::ResponseKernel> delayedKernels() {
  std::vector<physics::ResponseKernel> k(3);
  k[0].lifetime_s = 2.5e-9;  // a fluorophore: 250 bins, past the axis's end
  k[0].fraction = 0.6;
  k[1].model = physics::ResponseModel::Gaussian;  // 64 taps: 3 chunks per class pass
  k[1].mean_s = 200e-12;
  k[1].sigma_s = 40e-12;
  k[2].model = physics::ResponseModel::Table;
  k[2].tableDelay_s = {0.0, 50e-12, 300e-12};
  k[2].tableWeight = {0.0, 2.0, 0.5};
  k[2].fraction = 0.8;
  return k;
}

struct Contribution {
  physics::vec3 kernel;
  int responseClass;
};

// Deposits `contributions` (kPerPixel per pixel, in order) on GL and on the
// CPU, integrates them (the instant class, then class c >= 1 through the
// cascade stages[c - 1]) and expects the same volume and light off the axis.
// Returns the CPU's volume.
std::vector<float> expectCpuVolume(const std::vector<Contribution>& contributions,
                                   const std::vector<std::vector<physics::ResponseTaps>>& stages) {
  test::glTestContext();
  // Every uniform the backend sets must exist (restored after the test).
  struct StrictUniforms {
    bool before = gl::Program::strictUniforms();
    StrictUniforms() { gl::Program::setStrictUniforms(true); }
    ~StrictUniforms() { gl::Program::setStrictUniforms(before); }
  } strict;
  using physics::vec3;
  const std::size_t pixels = contributions.size() / kPerPixel;
  std::vector<float> packedKernels, packedEnergies;
  std::vector<vec3> energies;
  for (std::size_t i = 0; i < contributions.size(); ++i) {
    const vec3 e(0.3f + 0.01f * i, 0.7f / (1.0f + i), 1.1f + 0.5f * (i % 3));
    const vec3& k = contributions[i].kernel;
    energies.push_back(e);
    packedKernels.insert(packedKernels.end(),
                         {k.x, k.y, k.z, static_cast<float>(contributions[i].responseClass)});
    packedEnergies.insert(packedEnergies.end(), {e.r, e.g, e.b, 0.0f});
  }
  const std::size_t floats = pixels * kBins * 3;

  // GL: the gather, then the backend's integration (instant, then classes).
  gl::Buffer kernelBuffer(packedKernels.size() * sizeof(float), packedKernels.data());
  gl::Buffer energyBuffer(packedEnergies.size() * sizeof(float), packedEnergies.data());
  gl::Buffer volume(floats * sizeof(float));
  gl::Buffer lost(pixels * 2 * sizeof(float));
  volume.clear();
  PixelFootprint footprint(pixels, kBins, stages);
  footprint.beginSegment(pixels);
  kernelBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 20);
  energyBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 21);
  volume.bindBase(GL_SHADER_STORAGE_BUFFER, 22);
  lost.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kOutsideAxis);
  const gl::Program gather({{GL_COMPUTE_SHADER, "response_deposit_test.comp", gatherSource()}});
  gather.use();
  gather.set("uBins", kBins);
  gather.set("uResponseRegionPixels", static_cast<unsigned>(footprint.regionPixels()));
  gl::dispatchThreads(pixels, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  footprint.integrateInto(volume, pixels);
  std::vector<float> gpu(floats), gpuLost(pixels * 2);
  volume.download(0, floats * sizeof(float), gpu.data());
  lost.download(0, gpuLost.size() * sizeof(float), gpuLost.data());

  // CPU: each class into its own buffer, then the instant integration and
  // the delayed classes in order.
  std::vector<float> cpu(floats, 0.0f);
  for (std::size_t p = 0; p < pixels; ++p) {
    float* histogram = &cpu[p * kBins * 3];
    std::vector<std::vector<double>> diff(1 + stages.size(),
                                          std::vector<double>(static_cast<std::size_t>(kBins) * 3));
    std::vector<double> scratch(static_cast<std::size_t>(kBins) * 3);
    std::vector<bool> written(1 + stages.size(), false);
    physics::OffAxisSums off;
    for (int c = 0; c < kPerPixel; ++c) {
      const std::size_t k = p * kPerPixel + c;
      const auto cls = static_cast<std::size_t>(contributions[k].responseClass);
      physics::depositWide(diff[cls].data(), kBins, contributions[k].kernel, energies[k], off);
      written[cls] = true;
    }
    if (written[0]) physics::integrateFootprint(diff[0].data(), kBins, histogram);
    for (std::size_t c = 1; c <= stages.size(); ++c) {
      if (!written[c]) continue;
      const double past = physics::applyResponse(diff[c].data(), scratch.data(), kBins, 0,
                                                 stages[c - 1], histogram);
      if (past > 0.0) off.after += static_cast<float>(past);
    }
    EXPECT_NEAR(gpuLost[2 * p], off.before, 1e-6f * (1.0f + off.before)) << "pixel " << p;
    EXPECT_NEAR(gpuLost[2 * p + 1], off.after, 1e-6f * (1.0f + off.after)) << "pixel " << p;
  }
  std::size_t exact = 0, nonZero = 0;
  for (std::size_t i = 0; i < floats; ++i) {
    EXPECT_NEAR(gpu[i], cpu[i], 1e-6f * (1.0f + std::abs(cpu[i])))
        << "pixel " << i / (kBins * 3) << " bin " << i / 3 % kBins << " channel " << i % 3;
    if (std::abs(gpu[i] - cpu[i]) > 1e-6f * (1.0f + std::abs(cpu[i]))) break;  // the first only
    exact += gpu[i] == cpu[i];
    nonZero += cpu[i] != 0.0f;
  }
  std::printf("%zu of %zu values equal to the bit, %zu non-zero\n", exact, floats, nonZero);
  EXPECT_GT(nonZero, 3u * 1000u);  // the tails really spread

  // The passes clear what they read: a second integration adds nothing.
  footprint.integrateInto(volume, pixels);
  std::vector<float> again(floats);
  volume.download(0, floats * sizeof(float), again.data());
  EXPECT_EQ(again, gpu);
  EXPECT_GT(gpuLost[2 * 2 + 1], 0.01f);  // pixel 2's tails pass the end
  return cpu;
}

std::vector<std::vector<physics::ResponseTaps>> onePerClass(
    const std::vector<physics::ResponseKernel>& kernels) {
  std::vector<std::vector<physics::ResponseTaps>> stages;
  for (const physics::ResponseKernel& k : kernels) {
    stages.push_back({physics::responseTaps(k, kBin_s)});
  }
  return stages;
}

// Spikes, narrow and wide kernels of every class, some across the axis's
// ends, and a pixel without delayed light.
std::vector<Contribution> mixedContributions() {
  return {
      // an instant spike, delayed spikes of each class
      {{300.2f, 0.0f, 0.0f}, 0}, {{300.2f, 0.0f, 0.0f}, 1},
      {{40.7f, 0.0f, 0.0f}, 2},  {{800.5f, 0.0f, 0.0f}, 3},
      // narrow and wide kernels of one class, one instant wide
      {{600.0f, 2.5f, 0.5f}, 1}, {{900.0f, 60.0f, 20.0f}, 1},
      {{950.0f, 30.0f, 10.0f}, 0}, {{10.0f, 8.0f, 0.0f}, 2},
      // across the end, wholly after, across the start
      {{1495.0f, 30.0f, 5.0f}, 1}, {{1600.0f, 3.0f, 1.0f}, 2},
      {{-2.0f, 12.0f, 4.0f}, 3},   {{1400.0f, 0.0f, 0.0f}, 3},
      // a pixel without delayed light
      {{100.0f, 0.0f, 0.0f}, 0},   {{200.0f, 40.0f, 0.0f}, 0},
      {{300.0f, 1.0f, 0.2f}, 0},   {{400.3f, 0.0f, 0.0f}, 0}};
}

TEST(ResponseStageGLTest, DelayedClassesGiveTheCpuVolume) {
  expectCpuVolume(mixedContributions(), onePerClass(delayedKernels()));
}

TEST(ResponseStageGLTest, CascadesOfTwoAndThreeKernelsGiveTheCpuVolume) {
  // Class 1: exponential then Gaussian; 2: Gaussian, table, exponential (the
  // third stage reads the class's own region back); 3: the table alone.
  std::vector<physics::ResponseTaps> one;
  for (const physics::ResponseKernel& k : delayedKernels()) {
    one.push_back(physics::responseTaps(k, kBin_s));
  }
  const std::vector<float> cascades =
      expectCpuVolume(mixedContributions(), {{one[0], one[1]}, {one[1], one[2], one[0]}, {one[2]}});
  // The cascades are not the first member alone (the interim stage's).
  const std::vector<float> firsts =
      expectCpuVolume(mixedContributions(), {{one[0]}, {one[1]}, {one[2]}});
  EXPECT_NE(cascades, firsts);
}

TEST(ResponseStageGLTest, ReemissionGivesTheCpuVolume) {
  // G comes back as R and B, R as G; in a single kernel and inside cascades.
  std::vector<physics::ResponseKernel> kernels = delayedKernels();
  kernels[0].reemission[1] = glm::dvec3(0.7, 0.1, 0.15);
  kernels[2].reemission[0] = glm::dvec3(0.0, 0.9, 0.0);
  std::vector<physics::ResponseTaps> one;
  for (const physics::ResponseKernel& k : kernels) one.push_back(physics::responseTaps(k, kBin_s));
  const std::vector<float> volume = expectCpuVolume(
      mixedContributions(), {{one[0]}, {one[1], one[0]}, {one[2], one[1], one[0]}});
  // Against the same classes without the matrices: the channels changed.
  std::vector<physics::ResponseTaps> plain;
  for (const physics::ResponseKernel& k : delayedKernels()) {
    plain.push_back(physics::responseTaps(k, kBin_s));
  }
  EXPECT_NE(volume, expectCpuVolume(mixedContributions(), {{plain[0]},
                                                           {plain[1], plain[0]},
                                                           {plain[2], plain[1], plain[0]}}));
}
}  // namespace
}  // namespace tofsim::render
