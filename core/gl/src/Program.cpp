#include "tofsim/gl/Program.h"

#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <sstream>

#include "tofsim/gl/Check.h"
#include "tofsim/util/Error.h"

namespace tofsim::gl {

// Defined in the build-generated EmbeddedShaders.cpp.
const std::map<std::string, std::string, std::less<>>& embeddedShaders();

const std::string& embeddedShaderSource(std::string_view fileName) {
  const auto& shaders = embeddedShaders();
  const auto it = shaders.find(fileName);
  if (it == shaders.end()) {
    throw InputError(FileLoc{"shaders/" + std::string(fileName)}, "",
                     "shader was not embedded at build time");
  }
  return it->second;
}

namespace {

// Expands `#include "name"` lines with embedded files (one level is enough for
// our shared helpers, but recursion is allowed) and inserts the defines after
// the #version line.
std::string assemble(std::string_view fileName,
                     const std::vector<std::pair<std::string, std::string>>& defines, int depth) {
  if (depth > 8)
    throw InputError("shaders/" + std::string(fileName) + ": #include nested too deep");
  std::istringstream in(embeddedShaderSource(fileName));
  std::string out;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.rfind("#include \"", 0) == 0) {
      const std::size_t end = line.find('"', 10);
      out += assemble(line.substr(10, end - 10), {}, depth + 1);
      out += "#line " + std::to_string(lineNumber + 1) + "\n";
      continue;
    }
    out += line + "\n";
    if (depth == 0 && line.rfind("#version", 0) == 0) {
      for (const auto& [name, value] : defines) out += "#define " + name + " " + value + "\n";
      out += "#line " + std::to_string(lineNumber + 1) + "\n";
    }
  }
  return out;
}

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log.c_str();
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return log.c_str();
}

}  // namespace

Program::Program(const std::vector<ShaderStage>& stages,
                 const std::vector<std::pair<std::string, std::string>>& defines)
    : handle_(glCreateProgram()) {
  std::vector<Handle<detail::deleteShader>> shaders;
  std::string names;
  for (const ShaderStage& stage : stages) {
    const std::string source =
        stage.source.empty() ? assemble(stage.fileName, defines, 0) : stage.source;
    Handle<detail::deleteShader> shader(glCreateShader(stage.type));
    const char* text = source.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      throw InputError("shader shaders/" + stage.fileName +
                       " failed to compile: " + shaderLog(shader.id()));
    }
    glAttachShader(id(), shader.id());
    names += (names.empty() ? "" : ", ") + stage.fileName;
    shaders.push_back(std::move(shader));
  }
  glLinkProgram(id());
  GLint ok = 0;
  glGetProgramiv(id(), GL_LINK_STATUS, &ok);
  if (!ok) throw InputError("shader program (" + names + ") failed to link: " + programLog(id()));
  TOFSIM_GL_CHECK("Program link");
}

namespace {
#ifdef NDEBUG
bool strictUniforms_ = false;
#else
bool strictUniforms_ = true;
#endif
}  // namespace

void Program::setStrictUniforms(bool strict) { strictUniforms_ = strict; }
bool Program::strictUniforms() { return strictUniforms_; }

GLint Program::location(const char* name) const {
  const GLint location = glGetUniformLocation(id(), name);
  if (location < 0 && strictUniforms_) {
    checkFailed("location >= 0", __FILE__, __LINE__,
                std::string("uniform ") + name + " is not an active uniform of the program");
  }
  return location;
}

void Program::set(const char* name, int value) const {
  glProgramUniform1i(id(), location(name), value);
}
void Program::set(const char* name, unsigned value) const {
  glProgramUniform1ui(id(), location(name), value);
}
void Program::set(const char* name, float value) const {
  glProgramUniform1f(id(), location(name), value);
}
void Program::set(const char* name, const glm::vec2& v) const {
  glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec3& v) const {
  glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::ivec2& v) const {
  glProgramUniform2iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace tofsim::gl
