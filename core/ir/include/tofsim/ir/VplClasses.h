#pragma once
// A VPL's response class (physics::ResponseClassTable, issue 41): the
// multiset of the delays its light met from the light on, its own vertex's
// included, kept in Vpl::flux.w as an exact small integer (no reader of the
// record looks at flux.w otherwise; the GL backend always uploads it). Made
// once per VPL: a first-bounce (RSM) VPL's is single(k of its surface), a
// later bounce's then(its parent's class, k of its surface). A light on a
// delayed surface starts every path with its kernel: the table's row 0 is
// then that kernel's class (ResponseClassTable::build's start).

#include <cstdint>
#include <vector>

#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

/// The most delayed vertices a path of a render with indirect settings `s`
/// meets: one per VPL bounce and the pixel's own surface, and the light's own
/// surface where it delays (`start`, its base kernel: an NLOS laser spot on a
/// delayed relay wall). The depth of its ResponseClassTable.
inline int responseDepth(const capture::IndirectSettings& s, uint32_t start = 0) {
  return (s.enabled ? s.bounces + 1 : 1) + (start != 0 ? 1 : 0);
}

/// The response classes of a render (IrRenderer's; the config's check builds
/// the same): the scene's base kernels on paths of responseDepth, started by
/// the light's kernel `start`. Throws std::invalid_argument over
/// physics::kMaxResponseClasses.
inline physics::ResponseClassTable responseClasses(std::vector<physics::ResponseKernel> kernels,
                                                   const capture::IndirectSettings& s,
                                                   uint32_t start) {
  return physics::ResponseClassTable::build(std::move(kernels), responseDepth(s, start), start);
}

/// VPL v's class (flux.w).
inline uint32_t vplClassOf(const Vpl& v) { return static_cast<uint32_t>(v.flux.w); }

/// The class of a VPL of class `parent` continued to a surface of vertex
/// `vertex` (parent 0 for a first-bounce VPL). The table's depth holds every
/// path of the render (IrRenderer builds it with one delayed vertex per
/// bounce and one for the receiving sample).
inline float vplClassAfter(const physics::ResponseClassTable& classes, uint32_t parent,
                           const physics::ScatterVertex& vertex) {
  const uint32_t c = classes.then(parent, static_cast<uint32_t>(vertex.response));
  TOFSIM_CHECK_MSG(c != physics::ResponseClassTable::kNoClass,
                   "a VPL's path has more delayed vertices than its response class table holds");
  return static_cast<float>(c);
}

/// First-bounce VPLs: each one's class from its own surface (0 everywhere
/// without delays, as flux.w was before).
inline void setFirstBounceClasses(std::vector<Vpl>& vpls,
                                  const physics::ResponseClassTable& classes) {
  if (!classes.delayed()) return;
  for (Vpl& v : vpls) v.flux.w = vplClassAfter(classes, 0, v.vertex);
}

}  // namespace tofsim::ir
