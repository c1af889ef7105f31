#include "tofsim/gl/Check.h"

#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::gl {

namespace {
const char* errorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}
}  // namespace

void checkErrors(const char* what, const char* file, int line) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  if (e == GL_OUT_OF_MEMORY) {
    throw InputError(std::string("the GL implementation ran out of memory during ") + what +
                     "; lower render.memory_budget or the resolution");
  }
  checkFailed(what, file, line, errorName(e));
}

}  // namespace tofsim::gl
