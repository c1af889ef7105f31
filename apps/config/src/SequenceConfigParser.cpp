#include "SequenceConfigParser.h"

#include <cmath>
#include <string>

#include "FieldParse.h"
#include "QuantityText.h"
#include "SequenceFields.h"

namespace tofsim::config {

namespace {

// Frame times beyond it mean nothing for a glTF animation (its keyframe
// times are float seconds: a step of 64 s there) and print as numbers
// nobody can read; about 32 years of scene time.
constexpr double kMaxFrameTime_s = 1e9;

// Why frame time t (after `previous`, if any) cannot be one; "" when it can.
std::string frameTimeProblem(double t, const double* previous) {
  if (!(std::fabs(t) <= kMaxFrameTime_s)) {
    return "a frame time must be within +-" + durationText(kMaxFrameTime_s) +
           " (about 32 years of scene time; got " + readableDuration(t) + ")";
  }
  if (previous && !(t > *previous)) {
    return "frame times must increase: " + readableDuration(t) + " after " +
           readableDuration(*previous);
  }
  return "";
}

std::vector<double> parseTimes(const ConfigNode& node) {
  const ConfigNode list = node.child("times");
  if (!list.isSequence()) list.fail("expected a list of scene times, e.g. [0 s, 33 ms, 66 ms]");
  std::vector<double> times;
  for (const ConfigNode& e : list.elements()) {
    const double t = e.asDuration_s();
    const std::string problem = frameTimeProblem(t, times.empty() ? nullptr : &times.back());
    if (!problem.empty()) e.fail(problem);
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
    const double t = out.start_s + static_cast<double>(k) / out.rate_Hz;
    const std::string problem =
        frameTimeProblem(t, out.times_s.empty() ? nullptr : &out.times_s.back());
    if (!problem.empty()) {
      node.failKey(k == 0 ? "start" : "rate",
                   "frame " + std::to_string(k) + " at start + " + std::to_string(k) +
                       " / rate (rate " + frequencyText(out.rate_Hz) + "): " + problem);
    }
    out.times_s.push_back(t);
  }
  return out;
}

}  // namespace tofsim::config
