#pragma once
// The one place that includes the OpenGL API. Functions come from glvnd's
// libOpenGL, which exports every core entry point up to 4.6, so no loader is
// needed; the context decides at run time which ones work.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
