#pragma once
// The IR backends a render test runs on, for tests parametrised over them:
// the GL backend on the test program's shared context (llvmpipe in CI) and
// the CPU backend on 2 threads, both behind the one IR driver.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "support/GlTestContext.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::test {

enum class TestBackend { Gl, Cpu };

inline std::unique_ptr<capture::Renderer> makeTestRenderer(TestBackend backend) {
  if (backend == TestBackend::Cpu) {
    return std::make_unique<ir::IrRenderer>(
        std::make_unique<cpu::CpuBackend>(cpu::CpuBackendOptions{2, true}));
  }
  return std::make_unique<ir::IrRenderer>(std::make_unique<render::GlBackend>(glTestContext()));
}

inline std::string testBackendName(const ::testing::TestParamInfo<TestBackend>& info) {
  return info.param == TestBackend::Cpu ? "Cpu" : "Gl";
}

/// Fixture base: GetParam() is the backend; renderer() makes its renderer.
class BackendTest : public ::testing::TestWithParam<TestBackend> {
 protected:
  std::unique_ptr<capture::Renderer> renderer() const { return makeTestRenderer(GetParam()); }
};

}  // namespace tofsim::test

/// Runs every TEST_P of `Fixture` on both backends.
#define TOFSIM_ON_BOTH_BACKENDS(Fixture)                                                    \
  INSTANTIATE_TEST_SUITE_P(                                                                 \
      Backends, Fixture,                                                                    \
      ::testing::Values(::tofsim::test::TestBackend::Gl, ::tofsim::test::TestBackend::Cpu), \
      ::tofsim::test::testBackendName)
