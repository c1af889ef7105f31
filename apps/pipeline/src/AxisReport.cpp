#include "tofsim/pipeline/AxisReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "Warning.h"
#include "tofsim/physics/ResponseReach.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/sensors/WindowLoss.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {

namespace {

constexpr int32_t kMaxBins = config::kMaxTimeBins;

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}
std::string ns(double t_s) { return format("%.4g ns", t_s * 1e9); }
std::string percent(double fraction) { return format("%.3g%%", fraction * 100.0); }

// The axis on the same bin grid that also holds [shortest, longest] on the
// sides asked for, as the keys to set: "time.start: 4.7 ns, time.bins: 900
// would hold it all", or "" when the bounds suggest nothing larger. `fit`
// (an axis that misses all the light) moves the start onto the bounds even
// when that is later.
std::string suggestAxis(const TimeAxis& axis, const capture::ArrivalBounds& bounds, bool before,
                        bool after, bool fit = false) {
  if (!bounds.any) return "";
  const double w = axis.bin_width_s;
  double start = axis.start_s;
  if (fit || (before && bounds.shortest_s() < start)) {
    start += std::floor((bounds.shortest_s() - start) / w + 1e-9) * w;
    // Nothing arrives before the light's impulse at t = 0: a camera inside
    // the scene's box (a shortest bound of 0) needs a start of 0, not the
    // grid's step below it.
    if (start < 0.0 && bounds.shortest_s() >= 0.0) start = 0.0;
  }
  const double end = fit ? bounds.longest_s()
                         : (after ? std::max(axis.end_s(), bounds.longest_s()) : axis.end_s());
  const double bins = std::ceil((end - start) / w - 1e-9);
  std::string keys;
  // In both of the forms a config writes a start in (a user who wrote "8 m"
  // is not left to convert nanoseconds): c t is the optical path.
  if (start != axis.start_s) {
    keys = "time.start: " + ns(start) + format(" (%.4g m)", start * kSpeedOfLight_m_per_s);
  }
  if (bins != axis.bins) {
    keys += (keys.empty() ? "" : ", ") + std::string("time.bins: ") + format("%.0f", bins);
  }
  if (keys.empty()) return "";
  std::string text = "; " + keys + " would hold it all";
  if (bins > kMaxBins) text += " (over the limit of 2^20 bins: widen time.bin_width)";
  return text;
}

// The arrival bounds of `job`, the materials' delays included: each of a
// path's n delayed vertices (surfaceVertices) may add up to its kernel's
// reach at kWindowLossWarning / n, so that all n together leave at most
// kWindowLossWarning of the light beyond the sum (the union bound): n times
// the largest reach, the worst case of a path whose every vertex has the
// longest delay.
capture::ArrivalBounds boundsWithDelays(const config::RunConfig& config,
                                        const capture::RenderJob& job) {
  const int32_t n = surfaceVertices(config);
  capture::ArrivalBounds b = capture::arrivalBounds(job, n);
  double reach = 0.0;
  for (const scene::Material& m : job.scene->materials) {
    if (m.scatteringDelay) {
      reach = std::max(reach, physics::responseReach_s(*m.scatteringDelay, kWindowLossWarning / n));
    }
  }
  b.delay_s = n * reach;
  return b;
}

void warnOrThrow(const config::RunConfig& config, const std::string& key, const std::string& text) {
  if (config.strict) {
    throw InputError(FileLoc{config.config_file.string()}, key,
                     text + " (--strict / render.strict)");
  }
  warn(text);
}

}  // namespace

int32_t surfaceVertices(const config::RunConfig& config) {
  if (config.renderer == config::RendererKind::Reference) return config.reference.bounces;
  // The surface point the camera sees, plus one per indirect bounce.
  return config.render.indirect.enabled ? 1 + config.render.indirect.bounces : 1;
}

AxisPrediction predictAxisCut(const config::RunConfig& config, const capture::RenderJob& job) {
  const capture::ArrivalBounds b = boundsWithDelays(config, job);
  const TimeAxis& axis = job.settings.time;
  AxisPrediction p;
  if (!b.any) return p;
  const std::string bounds = "the scene's light arrives within " + ns(b.shortest_s()) + " .. " +
                             ns(b.longest_s()) + " (bounds from its box" +
                             (b.delay_s > 0.0 ? " and its materials' delays, " + ns(b.delay_s) : "") +
                             ", may be loose)";
  if (axis.end_s() <= b.shortest_s() || axis.start_s >= b.longest_s()) {
    const bool late = axis.end_s() <= b.shortest_s();
    p.verdict = AxisPrediction::Verdict::Cuts;
    p.message = std::string("the time axis ") +
                (late ? "ends at " + ns(axis.end_s()) : "starts at " + ns(axis.start_s)) + " but " +
                bounds + ": all of it arrives " +
                (late ? "after the last bin" : "before the first bin") +
                suggestAxis(axis, b, true, true, true);
  } else if (axis.start_s > b.shortest_s() || axis.end_s() < b.longest_s()) {
    p.verdict = AxisPrediction::Verdict::MayCut;
    p.message = "the time axis " + ns(axis.start_s) + " .. " + ns(axis.end_s()) +
                " may cut light off: " + bounds +
                suggestAxis(axis, b, axis.start_s > b.shortest_s(), axis.end_s() < b.longest_s());
  }
  return p;
}

namespace {

// A bin this many times wider than the whole span of the scene's arrivals
// cannot resolve anything: "time.bin_width: 10" read as 10 s rendered one
// bin with every pixel's light in it, and sensors computed depths from it.
// Bounds from the scene's box are loose (wider than the light), so only an
// axis that is hopeless by a wide margin is refused.
constexpr double kUnresolvedBinRatio = 100.0;

void requireResolvingAxis(const config::RunConfig& config, const capture::RenderJob& job) {
  const capture::ArrivalBounds b = boundsWithDelays(config, job);
  const double span = b.longest_s() - b.shortest_s();
  const TimeAxis& axis = job.settings.time;
  if (!b.any || !(span > 0.0) || axis.bin_width_s <= kUnresolvedBinRatio * span) return;
  const double suggested = std::max(span / 1000.0, 1e-13);
  throw InputError(FileLoc{config.config_file.string()}, "time.bin_width",
                   "one bin of " + ns(axis.bin_width_s) + " cannot resolve the scene's light, " +
                       "which arrives within " + ns(b.shortest_s()) + " .. " + ns(b.longest_s()) +
                       ": a bin width near " + format("%.3g ps", suggested * 1e12) +
                       " would (durations take units: '10 ps', '3 mm')");
}

}  // namespace

void checkAxisBeforeRender(const config::RunConfig& config, const capture::RenderJob& job,
                           bool notes) {
  requireResolvingAxis(config, job);
  const AxisPrediction p = predictAxisCut(config, job);
  if (p.verdict == AxisPrediction::Verdict::Cuts) warnOrThrow(config, "time", p.message);
  if (p.verdict == AxisPrediction::Verdict::MayCut && notes) {
    // A note, not a warning: the bounds are loose, most axes that end
    // inside them lose nothing. What is lost is measured by render, which
    // warns (the word of every cut) when it is more than kWindowLossWarning.
    std::fprintf(stderr, "tofsim: note: %s (render measures the cut and warns above %g %%)\n",
                 p.message.c_str(), 100.0 * kWindowLossWarning);
  }
}

AxisLossFractions axisLossFractions(const capture::RenderResult& result) {
  const double total = result.onAxisEnergy + result.offAxis.total();
  if (!(total > 0.0)) return {};
  return {result.offAxis.before / total, result.offAxis.after / total};
}

void checkAxisAfterRender(const config::RunConfig& config, const capture::RenderJob& job,
                          const capture::RenderResult& result) {
  const AxisLossFractions f = axisLossFractions(result);
  const TimeAxis& axis = job.settings.time;
  const bool before = f.before > kWindowLossWarning, after = f.after > kWindowLossWarning;
  if (before || after) {
    std::vector<std::string> sides;
    if (after)
      sides.push_back(percent(f.after) + " of the light arrives after the last bin (" +
                      ns(axis.end_s()) + ")");
    if (before)
      sides.push_back(percent(f.before) + " of the light arrives before the first bin (" +
                      ns(axis.start_s) + ")");
    const capture::ArrivalBounds b = boundsWithDelays(config, job);
    warnOrThrow(config, "time",
                sides[0] + (sides.size() > 1 ? " and " + sides[1] : "") +
                    suggestAxis(axis, b, before, after, !(result.onAxisEnergy > 0.0)));
  }
}

void checkSensorWindow(const config::RunConfig& config, std::size_t index, double lost,
                       const TimeAxis& axis) {
  if (lost <= kWindowLossWarning) return;
  const sensors::SensorSpec& spec = config.sensors[index];
  warnOrThrow(config, "sensors[" + std::to_string(index) + "]",
              "sensor '" + spec.name + "' (" + sensors::sensorTypeName(spec.params) +
                  "): its instrument window drops " + percent(lost) +
                  " of the light it is given; without bin_offset and bins it takes the "
                  "render's time axis (" +
                  ns(axis.start_s) + " .. " + ns(axis.end_s()) + ")");
}

}  // namespace tofsim::pipeline
