#include "NlosFirstBounce.h"

#include <cmath>
#include <optional>

#include "tofsim/capture/Light.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {

namespace {

// The relay wall's scattering delay on the axis' bins (the spot's one
// delayed vertex), none for an instant wall.
std::optional<physics::ResponseTaps> wallResponse(const scene::Scene& scene,
                                                  const capture::Light& spot,
                                                  const TimeAxis& axis) {
  const ir::MaterialResponses responses = ir::materialResponses(scene);
  const uint32_t k = ir::lightResponse(responses, spot);
  if (k == 0) return std::nullopt;
  return physics::responseTaps(responses.kernels[k - 1], axis.bin_width_s);
}

// A spike of `rgb` in bin `bin` through the wall's delay (the stage's exact
// bin integrals, as a delayed class of one member), written as R + G + B
// into column `column` of H (time slowest, `points` columns).
void depositDelayed(const physics::ResponseTaps& wall, const glm::vec3& rgb, int32_t bin,
                    const TimeAxis& axis, std::size_t points, std::size_t column,
                    std::vector<float>& out) {
  const auto bins = static_cast<std::size_t>(axis.bins);
  std::vector<double> diff(bins * 3, 0.0);
  std::vector<float> histogram(bins * 3, 0.0f);
  physics::OffAxisSums lost;
  physics::depositWide(diff.data(), axis.bins,
                       glm::vec3(static_cast<float>(bin) + 0.5f, 0.0f, 0.0f), rgb, lost);
  (void)physics::applyResponse(diff.data(), axis.bins, bin, wall, histogram.data());
  for (std::size_t n = static_cast<std::size_t>(bin); n < bins; ++n) {
    const float* h = &histogram[n * 3];
    out[n * points + column] = h[0] + h[1] + h[2];
  }
}

}  // namespace

std::vector<float> nlosFirstBounce(const config::RunConfig& config, const NlosScanGeometry& scan,
                                   const scene::Scene& scene, const TimeAxis& axis) {
  const std::size_t perCapture = scan.pointsPerCapture();
  const std::size_t points = scan.captureCount() * perCapture;
  std::vector<float> out(static_cast<std::size_t>(axis.bins) * points, 0.0f);
  const float cellX = scan.wall.width_m / static_cast<float>(scan.sensorGrid[0]);
  const float cellY = scan.wall.height_m / static_cast<float>(scan.sensorGrid[1]);
  const double cellArea = static_cast<double>(cellX) * cellY;
  const bool legs = config.nlos->account_first_and_last_bounces;
  for (std::size_t c = 0; c < scan.captureCount(); ++c) {
    const NlosCapture capture = scan.capture(c, config, scene);
    const glm::vec3 l = scan.laserPoints[c];
    // The spot's power leaving the wall: its intensity on the normal is
    // albedo x power / pi (NlosScan::capture), and a Lambertian spot sends
    // pi x that intensity into its hemisphere.
    const glm::vec3 rgb = capture.laser.intensity_W_per_sr * static_cast<float>(M_PI);
    const double exitance = (double(rgb.r) + rgb.g + rgb.b) / cellArea;
    // The wall is the spot's one scattering vertex: its delay, once.
    const std::optional<physics::ResponseTaps> wall = wallResponse(scene, capture.laser, axis);
    for (std::size_t k = 0; k < perCapture; ++k) {
      const glm::vec3 s = capture.points.points_world[k];
      const glm::vec3 d = l - s;
      if (std::fabs(glm::dot(d, scan.wall.x_axis)) > 0.5f * cellX ||
          std::fabs(glm::dot(d, scan.wall.y_axis)) > 0.5f * cellY) {
        continue;
      }
      double path_m = 0.0;
      if (legs) {
        path_m = axis.index_of_refraction *
                 (glm::length(scan.laserOrigin - l) + glm::length(s - scan.sensorOrigin));
      }
      const double bin = std::floor((path_m - axis.start_m()) / axis.bin_width_m());
      if (bin < 0.0 || bin >= axis.bins) continue;
      if (wall) {
        const glm::vec3 radiance = rgb / static_cast<float>(cellArea * M_PI);
        depositDelayed(*wall, radiance, static_cast<int32_t>(bin), axis, points, c * perCapture + k,
                       out);
        continue;
      }
      out[static_cast<std::size_t>(bin) * points + c * perCapture + k] =
          static_cast<float>(exitance / M_PI);
    }
  }
  return out;
}

}  // namespace tofsim::pipeline
