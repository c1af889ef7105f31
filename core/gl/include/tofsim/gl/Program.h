#pragma once
// A linked GL program built from shaders embedded at build time (files under
// shaders/). Variants are made by prepending #defines, never by copying files.
// Compile and link errors name the shader file and carry the driver's log.

#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tofsim/gl/Handle.h"

namespace tofsim::gl {

/// Source of an embedded shader by file name, e.g. "gbuffer.vert".
/// Throws InputError naming the file when it was not embedded.
const std::string& embeddedShaderSource(std::string_view fileName);

struct ShaderStage {
  GLenum type;           ///< GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
  std::string fileName;  ///< under shaders/
  /// Test hook (a shader that fails to compile on purpose): when non-empty,
  /// compiled instead of the embedded file; fileName still names it in errors.
  std::string source = {};
};

class Program {
 public:
  Program() = default;
  /// `defines`: (NAME, value) pairs inserted after the #version line.
  Program(const std::vector<ShaderStage>& stages,
          const std::vector<std::pair<std::string, std::string>>& defines = {});

  GLuint id() const { return handle_.id(); }
  void use() const { glUseProgram(id()); }

  /// set() on a uniform the program does not have (never declared, or
  /// removed by the compiler as unused) is a bug at the call site: with strict
  /// uniforms it fails a TOFSIM_CHECK naming the uniform; otherwise it is
  /// ignored, as GL ignores location -1. Strict by default in debug builds
  /// (NDEBUG undefined); tests turn it on in any build.
  static void setStrictUniforms(bool strict);
  static bool strictUniforms();

  void set(const char* name, int value) const;
  void set(const char* name, unsigned value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::ivec2& value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  GLint location(const char* name) const;
  Handle<detail::deleteProgram> handle_;
};

}  // namespace tofsim::gl
