#include "RenderStatsJson.h"

#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/RenderStats.h"

namespace tofsim::pipeline {

nlohmann::json renderStatsJson(const capture::RenderResult& result) {
  const AxisLossFractions lost = axisLossFractions(result);
  nlohmann::json stats = {{"seconds", result.seconds},
                          {"segments", result.segments},
                          {"vpls", result.vpls},
                          {"vpl_batches", result.vplBatches},
                          {"sampled_pixels", result.sampledPixels},
                          {"peak_gpu_bytes", result.peakGpuBytes},
                          {"energy_outside_time_axis", result.offAxis.total()},
                          {"energy_before_axis", result.offAxis.before},
                          {"energy_after_axis", result.offAxis.after},
                          {"energy_on_axis", result.onAxisEnergy},
                          {"fraction_before_axis", lost.before},
                          {"fraction_after_axis", lost.after},
                          {"rejected_non_finite_values", result.nonFiniteRejected}};
  const capture::PassSeconds& pass = result.passSeconds;
  stats["pass_seconds"] = {
      {"surfaces", pass.surfaces}, {"vpls", pass.vpls},         {"visibility", pass.visibility},
      {"direct", pass.direct},     {"indirect", pass.indirect}, {"read_back", pass.readBack},
      {"other", pass.other}};
  return stats;
}

nlohmann::ordered_json nlosStatsJson(const NlosVolume& volume) {
  return {{"render_seconds", volume.seconds},
          {"captures", volume.captures},
          {"scene_preparations", volume.scenePreparations},
          {"vpls", volume.vpls},
          {"device", volume.device}};
}

std::string renderStatsText(const capture::RenderResult& result) {
  return renderStatsJson(result).dump();
}

std::string nlosStatsText(const NlosVolume& volume) { return nlosStatsJson(volume).dump(); }

}  // namespace tofsim::pipeline
