#pragma once
// Compute dispatch helpers.

#include <cstddef>
#include <cstdint>

namespace tofsim::gl {

/// Dispatches `threads` invocations of a kernel with local_size_x =
/// `groupSize` as a 2D grid of groups, since one dimension is limited to 65535
/// groups. The kernel computes its index as
///   gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * groupSize) + gl_GlobalInvocationID.x
/// and returns when it is >= threads.
void dispatchThreads(std::size_t threads, uint32_t groupSize);

}  // namespace tofsim::gl
