#pragma once
// output.plot_ranges as the picture writers use it: each picture asks for its
// fixed range by its path without ".png" ("depth", "sensors/spad/spad_intensity"),
// and a key that no picture asked for is reported, so a typo is not silently
// ignored (the picture names depend on the sensors, so the config loader
// cannot check them).

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tofsim::pipeline {

class PlotRanges {
 public:
  using Map = std::map<std::string, std::array<double, 2>>;
  explicit PlotRanges(const Map& ranges) : ranges_(ranges) {}

  /// The fixed range of picture `key`, if the config gives one.
  std::optional<std::array<double, 2>> take(const std::string& key) {
    const auto it = ranges_.find(key);
    if (it == ranges_.end()) return std::nullopt;
    taken_.insert(key);
    return it->second;
  }

  /// Keys starting with `prefix` that no picture took.
  std::vector<std::string> untaken(const std::string& prefix) const {
    std::vector<std::string> keys;
    for (const auto& [key, range] : ranges_) {
      if (key.rfind(prefix, 0) == 0 && !taken_.count(key)) keys.push_back(key);
    }
    return keys;
  }

 private:
  const Map& ranges_;
  std::set<std::string> taken_;
};

/// Prints "tofsim: warning: output.plot_ranges.<key> names no picture of this
/// run" on stderr (also with -q) for each key of `keys`.
void warnUntakenPlotRanges(const std::vector<std::string>& keys);

}  // namespace tofsim::pipeline
