#include "tofsim/pipeline/ExitCode.h"

#include <cstdio>
#include <exception>
#include <new>

#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

int exitCodeOf(const std::function<int()>& body) {
  try {
    return body();
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "tofsim: %s\n", e.what());
    return e.exitCode();
  } catch (const InputError& e) {
    std::fprintf(stderr, "tofsim: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "tofsim: error: out of memory (the video, frames and sensors hold the whole "
                 "volume in host memory: lower camera.resolution or time.bins)\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tofsim: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace tofsim::pipeline
