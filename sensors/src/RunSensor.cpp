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

std::unique_ptr<SensorStream> openSensor(const SensorSpec& spec, const VolumeShape& shape,
                                         const StreamOptions& options) {
  return std::visit([&](const auto& p) { return TypeOf<decltype(p)>::open(p, shape, options); },
                    spec.params);
}

std::vector<SensorOutput> runSensor(const SensorSpec& spec, const SensorInputs& in) {
  TOFSIM_CHECK(in.volume != nullptr);
  const TransientVolume* direct = in.directOnly;
  const auto sameShape = [&](const TransientVolume& v) {
    return v.width() == in.volume->width() && v.height() == in.volume->height() &&
           v.channels() == in.volume->channels() && v.bins() == in.volume->bins();
  };
  if (direct && !sameShape(*direct)) {
    throw InputError("the direct-only volume does not match the volume's shape");
  }
  StreamOptions options;
  options.seed = in.seed;
  options.directOnly = direct != nullptr;
  if (in.bounces) {
    if (!direct) throw InputError("bounce components need the direct component too");
    for (const TransientVolume* b : *in.bounces) {
      TOFSIM_CHECK(b != nullptr);
      if (!sameShape(*b)) throw InputError("a bounce volume does not match the volume's shape");
    }
    options.bounces = static_cast<int32_t>(in.bounces->size());
  }
  const std::unique_ptr<SensorStream> stream = openSensor(spec, shapeOf(*in.volume), options);
  stream->consume(wholeVolume(*in.volume, direct, in.bounces));
  return stream->finish(in.groundTruthDepth_m);
}

std::vector<std::string> sensorWarnings(const SensorSpec& spec, const SensorInputs& in) {
  TOFSIM_CHECK(in.volume != nullptr);
  return sensorWarnings(spec, shapeOf(*in.volume), in.groundTruthDepth_m);
}

std::vector<std::string> sensorWarnings(const SensorSpec& spec, const VolumeShape& shape,
                                        const Image* groundTruthDepth_m) {
  return std::visit(
      [&](const auto& p) { return TypeOf<decltype(p)>::warnings(p, shape, groundTruthDepth_m); },
      spec.params);
}

}  // namespace tofsim::sensors
