#pragma once
// The response classes of a render (core/physics/temporal_response.md):
// which delays a contribution's light has been through on its way to the
// pixel. A vertex's temporal response is a *base kernel* (ScatterVertex::
// response: 0 instant, k >= 1 the scene's k-th distinct kernel,
// ir::materialResponses); a path's is the multiset of the base kernels of the
// delayed vertices it met (a VPL's: its whole history, its own vertex
// included), a *class*: class 0 is the instant one, every other class is the
// cascade of its members' kernels. Delays are linear and time-invariant, so
// their order along the path does not matter for the time axis; a class is a
// sorted list of base ids.
//
// A gather finds the class of a contribution by `then(vplClass, k)`: the
// VPL's class followed by the receiving vertex's base kernel k. The table
// holds every class a path of at most `maxDelayedVertices` delayed vertices
// can reach, numbered once here for both backends (GL reads `compose` as a
// buffer).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::physics {

/// Most classes a render may have (each costs a difference buffer per pixel:
/// the memory plan counts them).
inline constexpr std::size_t kMaxResponseClasses = 64;

struct ResponseClassTable {
  /// Base kernels: kernels[k - 1] is base kernel k (k >= 1).
  std::vector<ResponseKernel> kernels;
  /// members[c]: class c's base kernels, ascending (members[0] empty).
  std::vector<std::vector<uint32_t>> members;
  /// compose[c * (kernels.size() + 1) + k]: the class of a path of class c
  /// that then meets a vertex of base kernel k (k = 0: c itself); kNoClass
  /// where that path would exceed the table's depth.
  std::vector<uint32_t> compose;
  static constexpr uint32_t kNoClass = 0xffffffffu;

  bool delayed() const { return members.size() > 1; }
  std::size_t classCount() const { return members.size(); }
  uint32_t then(uint32_t c, uint32_t k) const {
    return compose[static_cast<std::size_t>(c) * (kernels.size() + 1) + k];
  }
  /// The class of a single vertex of base kernel k (the pixel's own surface
  /// lit directly).
  uint32_t single(uint32_t k) const { return then(0, k); }

  /// Every class of at most `maxDelayedVertices` delayed vertices among
  /// `baseKernels`, in order of size, then lexicographic. Throws
  /// std::invalid_argument over kMaxResponseClasses (the caller says which
  /// setting to lower).
  static ResponseClassTable build(std::vector<ResponseKernel> baseKernels,
                                  int maxDelayedVertices) {
    ResponseClassTable t;
    t.kernels = std::move(baseKernels);
    const auto k = static_cast<uint32_t>(t.kernels.size());
    t.members.push_back({});
    std::map<std::vector<uint32_t>, uint32_t> id{{{}, 0u}};
    // Breadth first: the classes of size s + 1 from those of size s, each
    // extended by a base id >= its last member (every multiset once).
    std::size_t levelBegin = 0;
    for (int size = 0; size < maxDelayedVertices && k > 0; ++size) {
      const std::size_t levelEnd = t.members.size();
      for (std::size_t c = levelBegin; c < levelEnd; ++c) {
        const uint32_t from = t.members[c].empty() ? 1u : t.members[c].back();
        for (uint32_t b = from; b <= k; ++b) {
          std::vector<uint32_t> m = t.members[c];
          m.push_back(b);
          if (t.members.size() >= kMaxResponseClasses) {
            throw std::invalid_argument(
                std::to_string(k) + " delayed materials on paths of up to " +
                std::to_string(maxDelayedVertices) + " delayed vertices make over " +
                std::to_string(kMaxResponseClasses) + " response classes");
          }
          id.emplace(m, static_cast<uint32_t>(t.members.size()));
          t.members.push_back(std::move(m));
        }
      }
      levelBegin = levelEnd;
    }
    t.compose.assign(t.members.size() * (k + 1), kNoClass);
    for (std::size_t c = 0; c < t.members.size(); ++c) {
      t.compose[c * (k + 1)] = static_cast<uint32_t>(c);
      for (uint32_t b = 1; b <= k; ++b) {
        std::vector<uint32_t> m = t.members[c];
        m.insert(std::upper_bound(m.begin(), m.end(), b), b);
        const auto found = id.find(m);
        if (found != id.end()) t.compose[c * (k + 1) + b] = found->second;
      }
    }
    return t;
  }
};

/// Each delayed class's filter stages on an axis of bins `binWidth_s` wide:
/// [c - 1] holds class c's members' taps (responseTaps), in member order.
inline std::vector<std::vector<ResponseTaps>> classStages(const ResponseClassTable& table,
                                                          double binWidth_s) {
  std::vector<std::vector<ResponseTaps>> stages;
  for (std::size_t c = 1; c < table.classCount(); ++c) {
    std::vector<ResponseTaps> s;
    for (const uint32_t k : table.members[c]) {
      s.push_back(responseTaps(table.kernels[k - 1], binWidth_s));
    }
    stages.push_back(std::move(s));
  }
  return stages;
}

/// Whether some class is a cascade of several kernels (its stage then needs
/// a scratch buffer per pixel: GL's footprint buffer holds one more region).
inline bool hasCascades(const ResponseClassTable& table) {
  return std::any_of(table.members.begin(), table.members.end(),
                     [](const std::vector<uint32_t>& m) { return m.size() > 1; });
}

/// The difference buffers per pixel of a segment (bins x 3 doubles each)
/// that the table's classes add to the instant one's: one per delayed class
/// and a scratch for the cascades (what the memory plan counts).
inline std::size_t responseBuffers(const ResponseClassTable& table) {
  return table.classCount() - 1 + (hasCascades(table) ? 1 : 0);
}

}  // namespace tofsim::physics
