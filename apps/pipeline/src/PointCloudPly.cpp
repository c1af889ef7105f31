#include "tofsim/pipeline/PointCloudPly.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

constexpr const char* kProperties[] = {"x",     "y",     "z",         "cam_x",
                                       "cam_y", "cam_z", "intensity", "confidence"};

// Little-endian bytes of a float whatever the host's order.
void appendFloat(std::vector<unsigned char>& out, float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<unsigned char>(bits >> (8 * b)));
}

float valueOr(const Image* image, int32_t y, int32_t x, float fallback) {
  return image ? image->at(y, x, 0) : fallback;
}

}  // namespace

std::size_t writePointCloudPly(const std::filesystem::path& path, const PointCloudImages& images,
                               const capture::Camera& camera) {
  TOFSIM_CHECK(images.depth_m != nullptr);
  const Image& depth = *images.depth_m;
  TOFSIM_CHECK(depth.channels == 1 && depth.width == camera.width && depth.height == camera.height);
  for (const Image* other : {images.intensity, images.confidence, images.mask}) {
    TOFSIM_CHECK(!other || (other->width == depth.width && other->height == depth.height &&
                            other->channels == 1));
  }
  const capture::PixelRays rays(camera);
  const glm::dvec3 origin(camera.position_world);
  const glm::dvec3 right(camera.right()), down(-glm::dvec3(camera.up())), forward(camera.forward());
  std::vector<unsigned char> body;
  std::size_t points = 0;
  for (int32_t y = 0; y < depth.height; ++y) {
    for (int32_t x = 0; x < depth.width; ++x) {
      const double d = depth.at(y, x, 0);
      if (!std::isfinite(d) || (images.mask && images.mask->at(y, x, 0) == 0.0f)) continue;
      const glm::dvec3 dir(rays.direction(x, y));
      const glm::dvec3 world = origin + d * dir;
      const glm::dvec3 cam(d * glm::dot(dir, right), d * glm::dot(dir, down),
                           d * glm::dot(dir, forward));
      for (double v : {world.x, world.y, world.z, cam.x, cam.y, cam.z}) {
        appendFloat(body, static_cast<float>(v));
      }
      appendFloat(body, valueOr(images.intensity, y, x, 0.0f));
      appendFloat(body, valueOr(images.confidence, y, x, 1.0f));
      ++points;
    }
  }
  std::string header = "ply\nformat binary_little_endian 1.0\n";
  if (!images.comment.empty()) {
    std::string line = images.comment;  // one header line
    for (char& c : line) c = c == '\n' || c == '\r' ? ' ' : c;
    header += "comment " + line + "\n";
  }
  header +=
      "comment x y z: world frame, m; cam_x cam_y cam_z: camera frame (x right, y down, z "
      "forward), m\n";
  header += "element vertex " + std::to_string(points) + "\n";
  for (const char* p : kProperties) header += std::string("property float ") + p + "\n";
  header += "end_header\n";
  AtomicFile file(path);
  file.write(header);
  if (!body.empty()) file.write(body.data(), body.size());
  file.commit();
  return points;
}

}  // namespace tofsim::pipeline
