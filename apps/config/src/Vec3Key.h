#pragma once
// Private to the config module: a key holding [x, y, z], as a glm::vec3.

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "ConfigNode.h"

namespace tofsim::config {

inline glm::vec3 vec3Of(const ConfigNode& node, const std::string& key, const glm::vec3& fallback) {
  const std::vector<double> v = node.getDoubles(key, 3, {fallback.x, fallback.y, fallback.z});
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

}  // namespace tofsim::config
