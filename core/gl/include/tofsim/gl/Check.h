#pragma once
// GL error checking that records the call site. Out-of-memory is an
// environment problem (InputError, so main reports it); every other GL error is
// a tofsim bug and aborts with the function and line.

#include "tofsim/gl/GL.h"

namespace tofsim::gl {

void checkErrors(const char* what, const char* file, int line);

}  // namespace tofsim::gl

#define TOFSIM_GL_CHECK(what) ::tofsim::gl::checkErrors((what), __FILE__, __LINE__)
