#include "GlTestContext.h"

namespace tofsim::test {

gl::Context& glTestContext() {
  static gl::Context context;
  return context;
}

}  // namespace tofsim::test
