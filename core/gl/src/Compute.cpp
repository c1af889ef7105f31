#include "tofsim/gl/Compute.h"

#include <algorithm>

#include "tofsim/gl/GL.h"

namespace tofsim::gl {

void dispatchThreads(std::size_t threads, uint32_t groupSize) {
  const std::size_t groups = (threads + groupSize - 1) / groupSize;
  const std::size_t x = std::min<std::size_t>(std::max<std::size_t>(groups, 1), 65535);
  const std::size_t y = (groups + x - 1) / x;
  glDispatchCompute(static_cast<GLuint>(x), static_cast<GLuint>(std::max<std::size_t>(y, 1)), 1);
}

}  // namespace tofsim::gl
