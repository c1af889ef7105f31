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
  /// `baseKernels`, in order of size, then lexicographic. With a start
  /// kernel s >= 1 (the base kernel of the surface the light stands on: an
  /// NLOS laser spot's relay wall) every path begins with s: the table holds
  /// class 0 and the classes {s} + m for each m of at most
  /// `maxDelayedVertices` - 1 vertices (as many classes as a table one
  /// vertex shallower, plus {s}), and its row 0, "from the light", is {s}'s:
  /// single(k) is {s, k}, single(0) is {s}. Throws std::invalid_argument over
  /// kMaxResponseClasses (the caller says which setting to lower).
  static ResponseClassTable build(std::vector<ResponseKernel> baseKernels, int maxDelayedVertices,
                                  uint32_t start = 0) {
    ResponseClassTable t;
    t.kernels = std::move(baseKernels);
    const auto k = static_cast<uint32_t>(t.kernels.size());
    if (start > k) throw std::invalid_argument("a light's start kernel is not a base kernel");
    const int depth = start == 0 ? maxDelayedVertices : maxDelayedVertices - 1;
    // With a start kernel, class 0 is kept beside the classes that hold it.
    t.members = multisets(k, depth, start == 0 ? kMaxResponseClasses : kMaxResponseClasses - 1,
                          maxDelayedVertices);
    if (start != 0) {
      for (std::vector<uint32_t>& m : t.members)
        m.insert(std::upper_bound(m.begin(), m.end(), start), start);
      t.members.insert(t.members.begin(), std::vector<uint32_t>{});
    }
    std::map<std::vector<uint32_t>, uint32_t> id;
    for (std::size_t c = 0; c < t.members.size(); ++c)
      id.emplace(t.members[c], static_cast<uint32_t>(c));
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
    if (start != 0) {
      // Light leaves the light already through its start kernel (class 1, {s}).
      std::copy(t.compose.begin() + (k + 1), t.compose.begin() + 2 * (k + 1), t.compose.begin());
    }
    return t;
  }

 private:
  // Every multiset of at most `depth` ids among 1..k, the empty one first,
  // in order of size, then lexicographic; over `limit` of them throws (the
  // message names `reportedDepth` delayed vertices).
  static std::vector<std::vector<uint32_t>> multisets(uint32_t k, int depth, std::size_t limit,
                                                      int reportedDepth) {
    std::vector<std::vector<uint32_t>> out{{}};
    // Breadth first: the multisets of size s + 1 from those of size s, each
    // extended by an id >= its last member (every multiset once).
    std::size_t levelBegin = 0;
    for (int size = 0; size < depth && k > 0; ++size) {
      const std::size_t levelEnd = out.size();
      for (std::size_t c = levelBegin; c < levelEnd; ++c) {
        const uint32_t from = out[c].empty() ? 1u : out[c].back();
        for (uint32_t b = from; b <= k; ++b) {
          std::vector<uint32_t> m = out[c];
          m.push_back(b);
          if (out.size() >= limit) {
            throw std::invalid_argument(
                std::to_string(k) + " delayed materials on paths of up to " +
                std::to_string(reportedDepth) + " delayed vertices make over " +
                std::to_string(kMaxResponseClasses) + " response classes");
          }
          out.push_back(std::move(m));
        }
      }
      levelBegin = levelEnd;
    }
    return out;
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
