#pragma once
// A test shader around shaders/footprint_deposit.glsl: the file and what it
// includes (the kernel, the bin deposit) pasted in order (a test-hook source
// is not assembled), after the contract's bindings and the test's own
// defines and buffers, before the test's main. FootprintDepositGLTest and
// ResponseStageGLTest deposit through it.

#include <string>

#include "GpuContract.h"
#include "tofsim/gl/Program.h"

namespace tofsim::test {

inline std::string footprintDepositSource(int contributionsPerPixel, const std::string& defines,
                                          const char* buffers, const char* main) {
  std::string deposit = gl::embeddedShaderSource("footprint_deposit.glsl");
  for (const std::string include :
       {"#include \"footprint_kernel.glsl\"", "#include \"bin_deposit.glsl\""}) {
    deposit.replace(deposit.find(include), include.size(), "");
  }
  std::string source = "#version 450 core\n";
  for (const auto& [name, value] : render::gpu::shaderDefines()) {
    source += "#define " + name + " " + value + "\n";
  }
  source += "#define CONTRIBUTIONS " + std::to_string(contributionsPerPixel) + "\n";
  source += "#define GATHER_HISTOGRAM volume\n" + defines;
  return source + buffers + gl::embeddedShaderSource("footprint_kernel.glsl") +
         gl::embeddedShaderSource("bin_deposit.glsl") + deposit + main;
}

}  // namespace tofsim::test
