// The GL gathers' footprint deposit (shaders/footprint_deposit.glsl) and the
// integration pass (footprint_integrate.comp, through render::PixelFootprint)
// give the volume of the CPU's physics::depositContribution and
// integrateFootprint: spikes, narrow kernels, wide ones (tens to hundreds of
// bins), kernels across either end of the axis and wholly off it, several per
// pixel. The axis has more bins than one integration dispatch covers, so the
// running sums cross dispatches. Equal bytes on llvmpipe; the bound leaves
// room for a GPU compiler that fuses multiply-adds.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

namespace tofsim::render {
namespace {

// Over 2 x the integration's 6666 bins per dispatch: three dispatches.
constexpr int32_t kBins = 15000;
constexpr int kPerPixel = 4;  // contributions per pixel, in order

// What a gather declares before footprint_deposit.glsl.
const char* const kGatherBuffers = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 12) readonly buffer Kernels { vec4 kernels[]; };   // xyz kernel
layout(std430, binding = 13) readonly buffer Energies { vec4 energies[]; }; // rgb energy
layout(std430, binding = 14) buffer Volume { float volume[]; };
layout(std430, binding = 15) buffer Lost { float lost[]; };
uniform int uBins;
uniform vec3 uCameraPosition_world;
)";

// One invocation per pixel adds its contributions in order, as a gather does.
const char* const kGather = R"(
void main() {
  uint p = gl_GlobalInvocationID.x;
  float before = 0.0;
  float after = 0.0;
  for (uint c = 0u; c < uint(CONTRIBUTIONS); ++c) {
    uint k = p * uint(CONTRIBUTIONS) + c;
    depositContribution(p, kernels[k].xyz, energies[k].rgb, before, after);
  }
  lost[2u * p] = before;
  lost[2u * p + 1u] = after;
}
)";

std::string gatherSource() {
  return test::footprintDepositSource(kPerPixel, "", kGatherBuffers, kGather);
}

TEST(FootprintDepositGLTest, GatherAndIntegrationGiveTheCpuVolume) {
  test::glTestContext();
  using physics::vec3;
  // Per pixel, in order: (centre, wide, narrow) in bins.
  const std::vector<vec3> kernels = {
      // a spike, one inside a bin, a narrow one over 3 bins, a wide one
      {300.2f, 0.0f, 0.0f},
      {300.3f, 0.4f, 0.1f},
      {301.0f, 2.2f, 0.7f},
      {320.0f, 40.0f, 13.0f},
      // wide over the start, narrow over the start, a box, hundreds of bins
      {-3.0f, 40.0f, 13.0f},
      {0.2f, 1.5f, 0.5f},
      {7000.0f, 25.0f, 0.0f},
      {6666.0f, 500.0f, 200.0f},
      // across the end (narrow, wide), wholly before, wholly after
      {14999.5f, 1.0f, 0.5f},
      {14990.0f, 30.0f, 10.0f},
      {-50.0f, 20.0f, 5.0f},
      {15100.0f, 20.0f, 5.0f},
      // a pixel only of spikes and narrow kernels (never written to the buffer)
      {10.5f, 0.0f, 0.0f},
      {10.5f, 0.0f, 0.0f},
      {12.0f, 3.0f, 0.0f},
      {13333.9f, 0.9f, 0.9f}};
  const std::size_t pixels = kernels.size() / kPerPixel;
  std::vector<float> packedKernels, packedEnergies;
  std::vector<vec3> energies;
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    const vec3 e(0.3f + 0.01f * i, 0.7f / (1.0f + i), 1.1f + 0.5f * (i % 3));
    energies.push_back(e);
    packedKernels.insert(packedKernels.end(), {kernels[i].x, kernels[i].y, kernels[i].z, 0.0f});
    packedEnergies.insert(packedEnergies.end(), {e.r, e.g, e.b, 0.0f});
  }
  const std::size_t floats = pixels * kBins * 3;

  // GL: the gather, then the integration pass of the backend.
  gl::Buffer kernelBuffer(packedKernels.size() * sizeof(float), packedKernels.data());
  gl::Buffer energyBuffer(packedEnergies.size() * sizeof(float), packedEnergies.data());
  gl::Buffer volume(floats * sizeof(float));
  gl::Buffer lost(pixels * 2 * sizeof(float));
  volume.clear();
  PixelFootprint footprint(pixels, kBins);
  footprint.beginSegment(pixels);
  kernelBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 12);
  energyBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 13);
  volume.bindBase(GL_SHADER_STORAGE_BUFFER, 14);
  lost.bindBase(GL_SHADER_STORAGE_BUFFER, 15);
  const gl::Program gather({{GL_COMPUTE_SHADER, "footprint_deposit_test.comp", gatherSource()}});
  gather.use();
  gather.set("uBins", kBins);
  gl::dispatchThreads(pixels, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  footprint.integrateInto(volume, pixels);
  std::vector<float> gpu(floats), gpuLost(pixels * 2);
  volume.download(0, floats * sizeof(float), gpu.data());
  lost.download(0, gpuLost.size() * sizeof(float), gpuLost.data());

  // CPU: the same contributions through the shared C++.
  std::vector<float> cpu(floats, 0.0f);
  std::vector<double> diff(static_cast<std::size_t>(kBins) * 3);
  for (std::size_t p = 0; p < pixels; ++p) {
    std::fill(diff.begin(), diff.end(), 0.0);
    float* histogram = &cpu[p * kBins * 3];
    physics::OffAxisSums off;
    bool written = false;
    for (int c = 0; c < kPerPixel; ++c) {
      const std::size_t k = p * kPerPixel + c;
      written |=
          physics::depositContribution(histogram, diff.data(), kBins, kernels[k], energies[k], off);
    }
    if (written) physics::integrateFootprint(diff.data(), kBins, histogram);
    EXPECT_NEAR(gpuLost[2 * p], off.before, 1e-6f * (1.0f + off.before)) << "pixel " << p;
    EXPECT_NEAR(gpuLost[2 * p + 1], off.after, 1e-6f * (1.0f + off.after)) << "pixel " << p;
  }
  std::size_t exact = 0, nonZero = 0;
  for (std::size_t i = 0; i < floats; ++i) {
    // 1e-6 of a contribution's energy: far below one bin's share of a wide kernel.
    ASSERT_NEAR(gpu[i], cpu[i], 1e-6f)
        << "pixel " << i / (kBins * 3) << " bin " << i / 3 % kBins << " channel " << i % 3;
    exact += gpu[i] == cpu[i];
    nonZero += cpu[i] != 0.0f;
  }
  std::printf("%zu of %zu values equal to the bit, %zu non-zero\n", exact, floats, nonZero);
  EXPECT_GT(nonZero, 3u * 1000u);  // the wide kernels really spread

  // The pass clears what it read (the flags with it): a second one adds nothing.
  footprint.integrateInto(volume, pixels);
  std::vector<float> again(floats);
  volume.download(0, floats * sizeof(float), again.data());
  EXPECT_EQ(again, gpu);
}

}  // namespace
}  // namespace tofsim::render
