#include "tofsim/capture/Vignetting.h"

#include <glm/glm.hpp>

#include "tofsim/util/Error.h"

namespace tofsim::capture {

std::vector<float> vignettingGains(const Camera& camera, const Vignetting& vignetting) {
  switch (vignetting.kind) {
    case Vignetting::Kind::None:
      return {};
    case Vignetting::Kind::Map:
      TOFSIM_CHECK(vignetting.width == camera.width && vignetting.height == camera.height);
      return vignetting.map;
    case Vignetting::Kind::Cos4:
      break;
  }
  const PixelRays rays(camera);
  const glm::dvec3 forward = camera.forward();
  std::vector<float> gains;
  gains.reserve(static_cast<std::size_t>(camera.width) * camera.height);
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      const double c = glm::dot(glm::dvec3(rays.direction(x, y)), forward);
      gains.push_back(static_cast<float>(c * c * c * c));
    }
  }
  return gains;
}

}  // namespace tofsim::capture
