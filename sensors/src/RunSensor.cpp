// The dispatch over SensorParams: each call goes to the model's SensorType<>,
// with no branch per type to keep in step.
#include "tofsim/sensors/RunSensor.h"

#include <type_traits>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
template <typename P>
using TypeOf = SensorType<std::decay_t<P>>;
}  // namespace

const char* sensorTypeName(const SensorParams& params) {
  return std::visit([](const auto& p) -> const char* { return TypeOf<decltype(p)>::name; }, params);
}

std::uintmax_t sensorOutputBytes(const SensorParams& params, int32_t width, int32_t height,
                                 const TimeAxis& render) {
  return std::visit(
      [&](const auto& p) { return TypeOf<decltype(p)>::outputBytes(p, width, height, render); },
      params);
}

const SensorOutput* findOutput(const std::vector<SensorOutput>& outputs, const std::string& name,
                               SensorOutput::Kind kind) {
  for (const SensorOutput& o : outputs) {
    if (o.name == name && o.kind == kind) return &o;
  }
  return nullptr;
}

std::vector<SensorOutput> runSensor(const SensorSpec& spec, const SensorInputs& in) {
  TOFSIM_CHECK(in.volume != nullptr);
  return std::visit([&](const auto& p) { return TypeOf<decltype(p)>::run(p, in); }, spec.params);
}

std::vector<std::string> sensorWarnings(const SensorSpec& spec, const SensorInputs& in) {
  TOFSIM_CHECK(in.volume != nullptr);
  return std::visit([&](const auto& p) { return TypeOf<decltype(p)>::warnings(p, in); },
                    spec.params);
}

}  // namespace tofsim::sensors
