#pragma once
// One headless GL context for a whole GL test program (creating one per test
// would dominate the run time on llvmpipe).

#include "tofsim/gl/Context.h"

namespace tofsim::test {

gl::Context& glTestContext();

}  // namespace tofsim::test
