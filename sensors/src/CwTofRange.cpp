// What range a CW-ToF depth spans, how its per-frequency outputs are named,
// and the warning when the scene is deeper than that range.
#include <cmath>
#include <cstdio>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

double depthRange_m(const CwTofParams& p, double k) {
  TOFSIM_CHECK(!p.frequencies_Hz.empty() && k > 0.0);
  // One frequency is never unwrapped (unwrapDepth_m), whatever max_depth says.
  if (p.frequencies_Hz.size() == 1) return k / p.frequencies_Hz[0];
  return unwrapRange_m(p, k);
}

std::string frequencyLabel(double frequency_Hz) {
  char text[32];
  std::snprintf(text, sizeof text, "%gMHz", frequency_Hz / 1e6);
  return text;
}

std::vector<std::string> cwtofWarnings(const CwTofParams& p, const TimeAxis& axis,
                                       const Image* gt) {
  if (!gt) return {};
  float deepest = 0.0f;
  for (int32_t y = 0; y < gt->height; ++y) {
    for (int32_t x = 0; x < gt->width; ++x) {
      const float d = gt->at(y, x, 0);
      if (std::isfinite(d) && d > deepest) deepest = d;
    }
  }
  const double range = depthRange_m(p, axis.depthPerSecond_m_per_s());
  if (deepest <= range) return {};
  std::string freqs;
  for (double f : p.frequencies_Hz) freqs += (freqs.empty() ? "" : ", ") + frequencyLabel(f);
  char text[320];
  std::snprintf(text, sizeof text,
                "the scene's ground-truth depth reaches %.3f m, beyond the %.3f m unambiguous "
                "range of %s: depths beyond it wrap (cwtof_depth reads depth modulo %.3f m; the "
                "multipath errors are wrapped the same way)",
                deepest, range, freqs.c_str(), range);
  return {text};
}

}  // namespace tofsim::sensors
