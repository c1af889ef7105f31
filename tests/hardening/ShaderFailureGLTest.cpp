// A shader that does not compile must fail with an InputError naming the
// shader file and carrying the driver's log, not crash or render garbage.

#include <gtest/gtest.h>

#include "support/GlTestContext.h"
#include "tofsim/gl/Program.h"
#include "tofsim/util/Error.h"

namespace tofsim {
namespace {

TEST(ShaderFailureGLTest, CompileErrorNamesShaderAndHasDriverLog) {
  test::glTestContext();
  const std::string broken =
      "#version 450\nlayout(local_size_x = 1) in;\nvoid main() { undeclared_variable = 1; }\n";
  try {
    gl::Program program({{GL_COMPUTE_SHADER, "broken_on_purpose.comp", broken}});
    FAIL() << "a broken shader compiled";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shaders/broken_on_purpose.comp failed to compile"), std::string::npos)
        << what;
    EXPECT_NE(what.find("undeclared_variable"), std::string::npos) << "driver log: " << what;
  }
}

TEST(ShaderFailureGLTest, MissingEmbeddedShaderNamesFile) {
  test::glTestContext();
  EXPECT_THROW(gl::Program({{GL_COMPUTE_SHADER, "no_such_shader.comp"}}), InputError);
}

}  // namespace
}  // namespace tofsim
