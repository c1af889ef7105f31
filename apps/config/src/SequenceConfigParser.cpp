#include "SequenceConfigParser.h"

#include <cmath>
#include <string>

#include "FieldParse.h"
#include "SequenceFields.h"

namespace tofsim::config {

namespace {

std::vector<double> parseTimes(const ConfigNode& node) {
  const ConfigNode list = node.child("times");
  if (!list.isSequence()) list.fail("expected a list of scene times, e.g. [0 s, 33 ms, 66 ms]");
  std::vector<double> times;
  for (const ConfigNode& e : list.elements()) {
    const double t = e.asDuration_s();
    if (!std::isfinite(t)) e.fail("a frame time must be finite");
    if (!times.empty() && !(t > times.back())) {
      e.fail("frame times must increase: " + std::to_string(t) + " s after " +
             std::to_string(times.back()) + " s");
    }
    times.push_back(t);
  }
  if (times.empty()) list.fail("a sequence needs at least one frame");
  if (times.size() > 100000) list.fail("at most 100000 frames");
  return times;
}

}  // namespace

SequenceConfig parseSequence(const ConfigNode& node) {
  if (!node.isMap()) node.fail("expected a mapping (rate and count, or times)");
  SequenceConfig out;
  out.at = node.location();
  parseFields(node, kSequenceFields, out, [&](const char* key) {
    if (std::string(key) == "times" && node.has("times")) out.times_s = parseTimes(node);
  });
  if (node.has("times")) {
    for (const char* key : {"start", "rate", "count"}) {
      if (node.has(key)) node.failKey(key, "not with `times` (the list gives every frame's time)");
    }
    return out;
  }
  if (node.has("count") && out.count < 1)
    node.failKey("count", "a sequence needs at least one frame");
  if (!node.has("rate") || !node.has("count")) {
    node.fail("needs `rate` and `count` (frame k at start + k / rate), or `times`");
  }
  out.times_s.reserve(static_cast<std::size_t>(out.count));
  for (int32_t k = 0; k < out.count; ++k) {
    out.times_s.push_back(out.start_s + static_cast<double>(k) / out.rate_Hz);
    if (!std::isfinite(out.times_s.back())) {
      node.failKey("rate", "frame " + std::to_string(k) + "'s time start + k / rate is not finite");
    }
  }
  return out;
}

}  // namespace tofsim::config
