#pragma once
// The GL passes' guard flags (a uint the shaders atomicOr into, binding
// TOFSIM_SSBO_LOOP_GUARD): what each raised bit means, as an InputError, so
// that a render fails loudly instead of losing light.

#include <cstdint>
#include <string>

namespace tofsim::render {

/// An invocation came within a factor of two of llvmpipe's 65535 loop trips.
inline constexpr uint32_t kLoopTripsNearLimit = 1u;
/// A leg crossed a region's surface more often than the shaders keep
/// (medium_regions.glsl, render::kGlRegionCrossings).
inline constexpr uint32_t kRegionCrossingsOverflow = 2u;

/// Throws the InputError of the first raised bit of `flags`, saying that
/// `invocation` (e.g. "a gather invocation") raised it; nothing for 0.
void throwIfGuardRaised(uint32_t flags, const std::string& invocation);

}  // namespace tofsim::render
