// shaders/footprint_kernel.glsl compiles as GLSL and computes, on the GPU, the
// same difference-buffer deposits as its C++ face (FootprintBuffer.h): equal
// bytes on llvmpipe; the bound leaves room for a GPU compiler that fuses
// multiply-adds.

#include <gtest/gtest.h>

#include <vector>

#include "support/GlTestContext.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/gl/Program.h"
#include "tofsim/physics/FootprintBuffer.h"

namespace tofsim::gl {
namespace {

constexpr int32_t kBins = 600;

// One invocation per kernel; each writes its own pixel's difference buffer,
// slots in order, the loop a GL gather runs.
// (The test-hook source is not assembled: the kernel is pasted in below.)
const char* const kDeposit = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Kernels { vec4 kernels[]; };
layout(std430, binding = 1) buffer Diff { double diff[]; };
uniform int uBins;
void main() {
  uint p = gl_GlobalInvocationID.x;
  vec3 kernel = kernels[p].xyz;
  for (int slot = 0; slot < FOOTPRINT_SLOTS; ++slot) {
    int bin = footprintSlotBin(kernel, slot, uBins);
    if (bin >= 0) diff[p * uint(uBins) + uint(bin)] += footprintSlotValue(kernel, bin);
  }
}
)";

TEST(FootprintKernelGLTest, GlslDepositsEqualTheCppOnes) {
  test::glTestContext();
  using physics::vec3;
  const std::vector<vec3> kernels = {{300.2f, 0.0f, 0.0f},     {300.7f, 0.4f, 0.1f},
                                     {100.5f, 500.0f, 200.0f}, {-3.0f, 40.0f, 13.0f},
                                     {598.0f, 17.0f, 17.0f},   {250.0f, 3.5f, 0.0f}};
  std::vector<float> packed;
  for (const vec3& k : kernels) packed.insert(packed.end(), {k.x, k.y, k.z, 0.0f});
  Buffer kernelBuffer(packed.size() * sizeof(float), packed.data());
  std::vector<double> zeros(kernels.size() * kBins, 0.0);
  Buffer diffBuffer(zeros.size() * sizeof(double), zeros.data());
  kernelBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  diffBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  const std::string source =
      "#version 450 core\n" + embeddedShaderSource("footprint_kernel.glsl") + kDeposit;
  const Program program({{GL_COMPUTE_SHADER, "footprint_deposit_test.comp", source}});
  program.use();
  program.set("uBins", kBins);
  dispatchThreads(kernels.size(), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<double> gpu(zeros.size());
  diffBuffer.download(0, gpu.size() * sizeof(double), gpu.data());
  for (std::size_t p = 0; p < kernels.size(); ++p) {
    std::vector<double> cpu(static_cast<std::size_t>(kBins) * 3, 0.0);
    physics::depositFootprint(cpu.data(), kBins, kernels[p], vec3(1.0f));
    for (int32_t b = 0; b < kBins; ++b) {
      const double want = cpu[static_cast<std::size_t>(b) * 3];
      ASSERT_NEAR(gpu[p * kBins + b], want, 1e-12) << "kernel " << p << " bin " << b;
    }
  }
}

}  // namespace
}  // namespace tofsim::gl
