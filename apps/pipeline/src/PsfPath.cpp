#include "tofsim/pipeline/PsfPath.h"

#include <algorithm>
#include <variant>

#include "tofsim/pipeline/OutputProducts.h"

namespace tofsim::pipeline {

namespace {
// A sensor whose charges are the same linear map of every pixel's light.
bool psfOnItsRaws(const sensors::SensorSpec& spec) {
  const auto* cwtof = std::get_if<sensors::CwTofParams>(&spec.params);
  return cwtof && cwtof->delay_sigma_s == 0.0 && !cwtof->delay_map.present() &&
         !cwtof->multipath_by_order;
}
}  // namespace

PsfPath choosePsfPath(const config::RunConfig& config, bool forceTransient) {
  if (!config.camera.psf) return PsfPath::None;
  if (forceTransient) return PsfPath::Transient;
  const std::vector<OutputProduct> products = renderProducts(config);
  const bool needsTransient = std::any_of(products.begin(), products.end(), [](const auto& p) {
    return p.writer == Writer::Volume || p.writer == Writer::Frames || p.writer == Writer::Video;
  });
  if (needsTransient) return PsfPath::Transient;
  if (!std::all_of(config.sensors.begin(), config.sensors.end(), psfOnItsRaws)) {
    return PsfPath::Transient;
  }
  return PsfPath::Raws;
}

}  // namespace tofsim::pipeline
