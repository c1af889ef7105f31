#include "NlosFirstBounce.h"

#include <cmath>

#include "tofsim/capture/Light.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {

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
      out[static_cast<std::size_t>(bin) * points + c * perCapture + k] =
          static_cast<float>(exitance / M_PI);
    }
  }
  return out;
}

}  // namespace tofsim::pipeline
