#include "SensorListChecks.h"

#include <string>
#include <variant>
#include <vector>

#include "ShortestNumber.h"
#include "SpadTableFile.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {

// Sensor names become folder names (OUTDIR/sensors/<name>/): keep them plain
// and unique, so two sensors never write into the same place.
void checkSensorNames(const ConfigNode& list, const std::vector<sensors::SensorSpec>& specs) {
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const std::string& name = specs[i].name;
    const bool plain = !name.empty() && name != "." && name != ".." &&
                       name.find_first_not_of(
                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                           "0123456789_.-") == std::string::npos;
    if (!plain) {
      elements[i].failKey("name", "must be letters, digits, '_', '-' or '.' (got '" + name + "')");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (specs[j].name == name) {
        elements[i].failKey("name", "sensor name '" + name + "' is already used by sensors[" +
                                        std::to_string(j) + "]; give each sensor its own `name`");
      }
    }
  }
}

// A CW-ToF sensor's error by bounce order compares with the ground-truth
// depth, and needs the light split by bounce: the IR renderer's bounce
// components, or the reference's direct and indirect light when that is one
// bounce at most (render.reference.bounces <= 2).
void checkBounceOrders(const ConfigNode& list, const RunConfig& config) {
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const auto* cwtof = std::get_if<sensors::CwTofParams>(&config.sensors[i].params);
    if (!cwtof || !cwtof->multipath_by_order) continue;
    if (!config.output.depth) {
      elements[i].failKey("multipath_by_order",
                          "needs the ground-truth depth: set output.depth: true");
    }
    if (config.renderer == RendererKind::Reference && config.reference.bounces > 2) {
      elements[i].failKey(
          "multipath_by_order",
          "the reference renderer does not split its indirect light by bounce (render.reference."
          "bounces: " +
              std::to_string(config.reference.bounces) +
              "); use renderer: ir with render.indirect.bounces, or reference.bounces <= 2");
    }
  }
}

// A SPAD gate must open inside the TDC's window (its bins on the render's
// axis), or the detector never counts.
void checkSpadGates(const ConfigNode& list, const RunConfig& config) {
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const auto* spad = std::get_if<sensors::SpadParams>(&config.sensors[i].params);
    if (!spad) continue;
    const TimeAxis tdc = sensors::resolveBins(spad->bins, config.render.time);
    if (spad->tdc_dnl.present() && static_cast<int32_t>(spad->tdc_dnl.values.size()) != tdc.bins) {
      elements[i].failKey("tdc_dnl", "has " + std::to_string(spad->tdc_dnl.values.size()) +
                                         " values but the TDC has " + std::to_string(tdc.bins) +
                                         " bins (one DNL per bin)");
    }
    if (spad->tdc_dnl.present()) checkDnlSum(elements[i], spad->tdc_dnl);
    if (spad->gate_width_s <= 0.0) continue;
    const double g0 = spad->gate_start_s, g1 = g0 + spad->gate_width_s;
    if (!(g1 > tdc.start_s && g0 < tdc.end_s())) {
      elements[i].failKey("gate_start", "the gate [" + shortest(g0 * 1e9) + ", " +
                                            shortest(g1 * 1e9) +
                                            ") ns lies outside the TDC's "
                                            "window [" +
                                            shortest(tdc.start_s * 1e9) + ", " +
                                            shortest(tdc.end_s() * 1e9) + ") ns");
    }
    // A gate sweep's last position too (the positions move linearly).
    const double last =
        spad->gated_frames > 0 ? (spad->gate_positions - 1) * spad->gate_step_s : 0.0;
    if (!(g1 + last > tdc.start_s && g0 + last < tdc.end_s())) {
      elements[i].failKey("gate_step", "the last gate position [" + shortest((g0 + last) * 1e9) +
                                           ", " + shortest((g1 + last) * 1e9) +
                                           ") ns lies outside the TDC's window [" +
                                           shortest(tdc.start_s * 1e9) + ", " +
                                           shortest(tdc.end_s() * 1e9) + ") ns");
    }
  }
}

// The sensors' own check (sensors::checkChannelSelection, which runs when a
// sensor opens on the rendered volume) run here on the channel count the
// run will give them, so that a wrong count is a located error before
// anything renders rather than one without a line after it.
void checkSensorChannels(const ConfigNode& list, const RunConfig& config) {
  const int32_t channels = config.nlos ? 1 : capture::kChannels;
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const sensors::ChannelSelection& channel =
        std::visit([](const auto& p) { return p.common.channel; }, config.sensors[i].params);
    try {
      sensors::checkChannelSelection(channel, channels);
    } catch (const InputError& e) {
      const std::string volume = config.nlos ? " (an nlos capture's H)" : " (R, G, B)";
      elements[i].failKey(channel.weights.empty() ? "channel" : "channel_weights",
                          std::string(e.what()) + volume);
    }
  }
}

}  // namespace tofsim::config
