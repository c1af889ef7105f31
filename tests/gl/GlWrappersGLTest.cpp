// Each GL wrapper against the GL state it promises (in the manner of Magnum's
// BufferGLTest): sizes, round trips, moves that leave id 0 behind, and
// Program::set on a uniform the program lacks failing under strict uniforms.

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/gl/Framebuffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/gl/Texture.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::gl {
namespace {

static_assert(!std::is_copy_constructible_v<Buffer> &&
              std::is_nothrow_move_constructible_v<Buffer>);
static_assert(!std::is_copy_constructible_v<Texture> &&
              std::is_nothrow_move_constructible_v<Texture>);
static_assert(!std::is_copy_constructible_v<Program> &&
              std::is_nothrow_move_constructible_v<Program>);

class GlWrappersGLTest : public ::testing::Test {
 protected:
  void SetUp() override { test::glTestContext(); }
};

TEST_F(GlWrappersGLTest, BufferRoundTripsAndFills) {
  const std::vector<uint32_t> data = {1, 2, 3, 4};
  Buffer buffer(data.size() * 4, data.data());
  EXPECT_NE(buffer.id(), 0u);
  EXPECT_EQ(buffer.size(), 16u);
  std::vector<uint32_t> out(4);
  buffer.download(0, 16, out.data());
  EXPECT_EQ(out, data);
  const uint32_t seven = 7;
  buffer.upload(4, 4, &seven);
  buffer.download(4, 4, &out[1]);
  EXPECT_EQ(out[1], 7u);
  buffer.fill(0x7f800000u);
  buffer.download(0, 16, out.data());
  EXPECT_EQ(out, std::vector<uint32_t>(4, 0x7f800000u));
  buffer.clear();
  buffer.download(0, 16, out.data());
  EXPECT_EQ(out, std::vector<uint32_t>(4, 0u));
}

TEST_F(GlWrappersGLTest, MovedFromBufferHoldsNothing) {
  Buffer a(64);
  const GLuint id = a.id();
  Buffer b(std::move(a));
  EXPECT_EQ(b.id(), id);
  EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): the state moves promise
  Buffer c;
  c = std::move(b);
  EXPECT_EQ(c.id(), id);
  EXPECT_EQ(c.size(), 64u);
}

TEST_F(GlWrappersGLTest, TextureRoundTripsItsTexels) {
  Texture t = Texture::create2D(GL_RGBA32F, 3, 2);
  EXPECT_EQ(t.width(), 3);
  EXPECT_EQ(t.height(), 2);
  std::vector<float> in(3 * 2 * 4);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = static_cast<float>(i) * 0.5f;
  t.upload2D(GL_RGBA, GL_FLOAT, in.data());
  std::vector<float> out(in.size());
  t.download(GL_RGBA, GL_FLOAT, out.size() * sizeof(float), out.data());
  EXPECT_EQ(out, in);
  const Texture layers = Texture::create2DArray(GL_R32F, 4, 4, 6);
  EXPECT_EQ(layers.layers(), 6);
}

TEST_F(GlWrappersGLTest, FramebufferClearsItsAttachment) {
  Texture color = Texture::create2D(GL_RGBA32F, 2, 2);
  Texture depth = Texture::create2D(GL_DEPTH_COMPONENT32F, 2, 2);
  Framebuffer fb;
  fb.attachColor(0, color);
  fb.attachDepth(depth);
  fb.finish("test framebuffer");
  const float value[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, value);
  std::vector<float> out(16);
  color.download(GL_RGBA, GL_FLOAT, out.size() * sizeof(float), out.data());
  for (int p = 0; p < 4; ++p) EXPECT_EQ(out[p * 4 + 2], 0.75f);
}

const char* const kDoubler = R"(#version 450 core
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Values { uint values[]; };
uniform uint uCount;
uniform uint uFactor;
void main() {
  uint i = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (i < uCount) values[i] *= uFactor;
}
)";

TEST_F(GlWrappersGLTest, ComputeProgramRunsOverEveryThread) {
  const Program program({{GL_COMPUTE_SHADER, "doubler.comp", kDoubler}});
  std::vector<uint32_t> values(1000);
  for (uint32_t i = 0; i < values.size(); ++i) values[i] = i;
  Buffer buffer(values.size() * 4, values.data());
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  program.use();
  program.set("uCount", static_cast<unsigned>(values.size()));
  program.set("uFactor", 3u);
  dispatchThreads(values.size(), 64);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<uint32_t> out(values.size());
  buffer.download(0, out.size() * 4, out.data());
  for (uint32_t i = 0; i < out.size(); ++i) ASSERT_EQ(out[i], 3 * i);
}

// Restores the strictness a test changed.
class StrictUniforms {
 public:
  StrictUniforms() : before_(Program::strictUniforms()) { Program::setStrictUniforms(true); }
  ~StrictUniforms() { Program::setStrictUniforms(before_); }

 private:
  bool before_;
};

TEST_F(GlWrappersGLTest, SettingAnUndeclaredUniformIsAnError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const Program program({{GL_COMPUTE_SHADER, "doubler.comp", kDoubler}});
  const StrictUniforms strict;
  program.set("uFactor", 2u);  // declared and used: fine
  EXPECT_DEATH(program.set("uNoSuchUniform", 2u), "uniform uNoSuchUniform is not an active");
}

TEST_F(GlWrappersGLTest, RenderersSetOnlyUniformsTheirShadersDeclare) {
  const StrictUniforms strict;
  for (const capture::Visibility visibility :
       {capture::Visibility::Ism, capture::Visibility::Exact}) {
    test::CornerJob s(8);  // direct and indirect light: every pass and shader
    s.job.settings.indirect.visibility = visibility;
    capture::VolumeCollector out(s.job.camera().width, s.job.camera().height, s.job.settings.time,
                                 3);
    ir::IrRenderer(std::make_unique<render::GlBackend>(test::glTestContext())).render(s.job, out);
  }
}

}  // namespace
}  // namespace tofsim::gl
