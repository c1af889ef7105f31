#include "tofsim/sensors/Common.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::sensors {

namespace {
constexpr double kPlanck_J_s = 6.62607015e-34;  // exact by SI definition
}

double Radiometry::photoelectronsPerUnit() const {
  const double photonsPerJoule =
      wavelength_m > 0.0 ? wavelength_m / (kPlanck_J_s * kSpeedOfLight_m_per_s) : 1.0;
  return source_scale * etendue_m2sr * optics_transmission * quantum_efficiency * photonsPerJoule;
}

TimeAxis resolveBins(const InstrumentBins& bins, const TimeAxis& render) {
  TOFSIM_CHECK(bins.bin_width_s >= 0.0 && bins.count >= 0 && render.bin_width_s > 0.0);
  TimeAxis axis = render;  // the medium and the legs timed are the render's
  axis.bin_width_s = bins.bin_width_s > 0.0 ? bins.bin_width_s : render.bin_width_s;
  axis.start_s = bins.offset_s.value_or(render.start_s);
  if (bins.count > 0) {
    axis.bins = bins.count;
  } else {
    const double n = std::ceil((render.end_s() - axis.start_s) / axis.bin_width_s - 1e-9);
    axis.bins = std::max(1, static_cast<int32_t>(n));
  }
  return axis;
}

void checkChannelSelection(const ChannelSelection& channel, const TransientVolume& volume) {
  checkChannelSelection(channel, volume.channels());
}

void checkChannelSelection(const ChannelSelection& channel, int32_t c) {
  if (!channel.weights.empty()) {
    if (static_cast<int32_t>(channel.weights.size()) != c) {
      throw InputError("sensor channel_weights has " + std::to_string(channel.weights.size()) +
                       " weights but the volume has " + std::to_string(c) + " channels");
    }
  } else if (channel.index != ChannelSelection::kSumOfChannels &&
             (channel.index < 0 || channel.index >= c)) {
    throw InputError("sensor channel " + std::to_string(channel.index) +
                     " is out of range: the volume has " + std::to_string(c) + " channels");
  }
}

void pixelSignal(const TransientVolume& volume, const SensorCommon& common, int32_t y, int32_t x,
                 std::vector<double>& out) {
  pixelSignal(volume.data() + volume.index(y, x, 0, 0), volume.bins(), volume.channels(), common,
              out);
}

void pixelSignal(const float* p, int32_t T, int32_t C, const SensorCommon& common,
                 std::vector<double>& out) {
  const double scale = common.radiometry.photoelectronsPerUnit();
  out.assign(static_cast<std::size_t>(T), 0.0);
  const auto& w = common.channel.weights;
  for (int32_t t = 0; t < T; ++t) {
    double v = 0.0;
    if (w.empty() && common.channel.index == ChannelSelection::kSumOfChannels) {
      for (int32_t c = 0; c < C; ++c) v += p[static_cast<std::size_t>(t) * C + c];
    } else if (w.empty()) {
      v = p[static_cast<std::size_t>(t) * C + common.channel.index];
    } else {
      for (int32_t c = 0; c < C; ++c) v += w[c] * p[static_cast<std::size_t>(t) * C + c];
    }
    out[t] = v * scale;
  }
}

void resampleEnergy(const std::vector<double>& in, const TimeAxis& from, const TimeAxis& to,
                    std::vector<double>& out) {
  TOFSIM_CHECK(static_cast<int32_t>(in.size()) == from.bins);
  TOFSIM_CHECK(from.bin_width_s > 0.0 && to.bin_width_s > 0.0 && to.bins > 0);
  out.assign(static_cast<std::size_t>(to.bins), 0.0);
  for (int32_t i = 0; i < from.bins; ++i) {
    if (in[i] == 0.0) continue;
    const double a = from.binStart_s(i);
    const double b = a + from.bin_width_s;
    // Target bins overlapping [a, b), in units of target bins.
    const double ua = (a - to.start_s) / to.bin_width_s;
    const double ub = (b - to.start_s) / to.bin_width_s;
    const int64_t k0 = std::max<int64_t>(0, static_cast<int64_t>(std::floor(ua)));
    const int64_t k1 = std::min<int64_t>(to.bins - 1, static_cast<int64_t>(std::ceil(ub)) - 1);
    const double density = in[i] / (ub - ua);
    for (int64_t k = k0; k <= k1; ++k) {
      const double lo = std::max(ua, static_cast<double>(k));
      const double hi = std::min(ub, static_cast<double>(k + 1));
      if (hi > lo) out[k] += density * (hi - lo);
    }
  }
}

void resampleEnergyToEdges(const std::vector<double>& in, const TimeAxis& from,
                           const std::vector<double>& edges, std::vector<double>& out) {
  TOFSIM_CHECK(static_cast<int32_t>(in.size()) == from.bins && from.bin_width_s > 0.0);
  TOFSIM_CHECK(edges.size() >= 2);
  out.assign(edges.size() - 1, 0.0);
  // One sweep: source bin i and target bin k advance together.
  std::size_t k = 0;
  for (int32_t i = 0; i < from.bins && k < out.size(); ++i) {
    const double a = from.binStart_s(i), b = a + from.bin_width_s;
    const double density = in[i] / from.bin_width_s;
    while (k < out.size() && edges[k + 1] <= a) ++k;
    for (std::size_t j = k; j < out.size() && edges[j] < b; ++j) {
      const double overlap = std::min(b, edges[j + 1]) - std::max(a, edges[j]);
      if (overlap > 0.0) out[j] += density * overlap;
    }
  }
}

}  // namespace tofsim::sensors
