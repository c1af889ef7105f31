// The declared config keys (ConfigKeys.h). The README tables are checked
// against these rows by tests/config/ConfigKeysTest.cpp: change both together.
// The rows of a section with a parameter table come from it (RunFields.h,
// CameraFields.h, RaysFields.h, TimeFields.h, LightFields.h, OutputFields.h,
// NlosFields.h, SequenceFields.h; sensors: sensors/SensorFields.h); the
// literal rows below are the top level's.
#include "tofsim/config/ConfigKeys.h"

#include <iterator>

#include "CameraFields.h"
#include "FieldDoc.h"
#include "LightFields.h"
#include "NlosFields.h"
#include "OutputFields.h"
#include "RaysFields.h"
#include "RunFields.h"
#include "SequenceFields.h"
#include "TimeFields.h"
#include "tofsim/sensors/SensorFields.h"

namespace tofsim::config {

namespace {
// clang-format off
const ConfigKey kRunConfigKeys[] = {
    {"scene", "string", "", "required", "-",
     "glTF file, relative to the config's folder"},
    {"camera", "mapping", "", "required", "-",
     "see below (`{}` for all defaults); not with `nlos`"},
    {"light", "mapping", "", "required", "-",
     "see below; not with `nlos`"},
    {"rays", "mapping", "", "none", "-",
     "a capture whose pixels are the rays of a file (a fibre bundle, a scanning pattern, a custom lens) instead of `camera`, see below; not with `camera`, `nlos` or `sequence`"},
    {"nlos", "mapping", "", "none", "-",
     "a non-line-of-sight relay-wall scan instead of `camera` and `light`, see below"},
    {"sequence", "mapping", "", "none", "-",
     "a capture sequence of the scene's glTF animations (frames at their own scene times) instead of one capture at the rest pose, see below; not with `nlos`"},
    {"time", "mapping", "", "required", "-",
     "see below"},
    {"render", "mapping", "", "defaults", "-",
     "see below"},
    {"output", "mapping", "", "defaults", "-",
     "see below"},
    {"sensors", "list", "", "none", "-",
     "sensor models run on the volume, see below"},
};
// The keys of a sensor entry itself, and the one-of-two channel keys; every
// other sensor key's row comes from its parameter table (SensorFields.h).
const ConfigKey kSensorEntryKeys[] = {
    {"common.type", "string", "", "required", "-",
     "`streak`, `spad` or `cwtof`"},
    {"common.name", "string", "", "the type", "-",
     "label of this sensor"},
    {"common.channel", "int", "", "0", "-",
     "volume channel used when `channel_weights` is absent"},
    {"common.channel_weights", "list of numbers", "", "none", "-",
     "weighted sum of the channels instead (one weight per channel)"},
};
// clang-format on
}  // namespace

std::span<const ConfigKey> runConfigKeys() {
  static const DocRows rows = [] {
    DocRows r;
    r.keys.assign(std::begin(kRunConfigKeys), std::end(kRunConfigKeys));
    addDocRows<CameraConfig>(r, "camera", kCameraFields);
    addDocRows<capture::Lens>(r, "camera.lens", kLensFields);
    addDocRows<PsfConfig>(r, "camera.psf", kPsfFields);
    addDocRows<RaysConfig>(r, "rays", kRaysFields);
    addDocRows<LightConfig>(r, "light", kLightFields);
    addDocRows(r, "time", kTimeFields, RunConfig{}.render.time);
    addDocRows<RunConfig>(r, "render", kRenderFields);
    addDocRows<capture::IndirectSettings>(r, "render.indirect", kIndirectFields);
    addDocRows<ReferenceConfig>(r, "render.reference", kReferenceFields);
    addDocRows<NlosConfig>(r, "nlos", kNlosFields);
    addDocRows<SequenceConfig>(r, "sequence", kSequenceFields);
    addDocRows<OutputConfig>(r, "output", kOutputFields);
    return r;
  }();
  return rows.keys;
}
std::span<const ConfigKey> sensorConfigKeys() {
  static const DocRows rows = [] {
    DocRows r;
    r.keys.assign(std::begin(kSensorEntryKeys), std::end(kSensorEntryKeys));
    addDocRows<sensors::Radiometry>(r, "common", sensors::kRadiometryFields);
    addDocRows<sensors::InstrumentBins>(r, "bins", sensors::kBinsFields);
    addDocRows<sensors::StreakParams>(r, "streak", sensors::kStreakFields);
    addDocRows<sensors::SpadParams>(r, "spad", sensors::kSpadFields);
    addDocRows<sensors::CwTofParams>(r, "cwtof", sensors::kCwTofFields);
    return r;
  }();
  return rows.keys;
}

}  // namespace tofsim::config
