#include "tofsim/capture/Imager.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tofsim/capture/RelayWall.h"
#include "tofsim/physics/FootprintKernel.h"
#include "tofsim/scene/Scene.h"
#include "tofsim/util/Error.h"

namespace tofsim::capture {

namespace {
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Clang 14 (the fuzz build) has no aggregate deduction, C++20's P1816.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;
}  // namespace

int32_t imageWidth(const Imager& imager) {
  return std::visit([](const auto& i) { return i.width; }, imager);
}

int32_t imageHeight(const Imager& imager) {
  return std::visit([](const auto& i) { return i.height; }, imager);
}

glm::vec3 viewpoint(const Imager& imager) {
  return std::visit(Overloaded{[](const Camera& c) { return c.position_world; },
                               [](const PointSetImager& p) { return p.origin_world; },
                               // One of them: each sample carries its own
                               // (raysShareOrigin is false).
                               [](const RayListImager& r) {
                                 return r.rays.empty() ? glm::vec3(0.0f) : r.rays[0].origin;
                               }},
                    imager);
}

bool lastLegCounts(const Imager& imager) {
  return std::visit(Overloaded{[](const Camera&) { return true; },
                               [](const PointSetImager& p) { return p.last_leg_counts; },
                               [](const RayListImager& r) { return r.last_leg_counts; }},
                    imager);
}

const Camera* pinhole(const Imager& imager) {
  const Camera* camera = std::get_if<Camera>(&imager);
  return camera != nullptr && !camera->lens && !camera->defocused() ? camera : nullptr;
}

const Camera* cameraOf(const Imager& imager) { return std::get_if<Camera>(&imager); }

void checkLayout(const Imager& imager) {
  std::visit(Overloaded{[](const Camera&) {},
                        [](const PointSetImager& p) {
                          if (p.points_world.size() ==
                              static_cast<std::size_t>(p.width) * p.height)
                            return;
                          throw InputError("the point-set imager lays out " +
                                           std::to_string(p.width) + "x" +
                                           std::to_string(p.height) + " pixels but holds " +
                                           std::to_string(p.points_world.size()) + " points");
                        },
                        [](const RayListImager& r) {
                          if (r.rays.size() == static_cast<std::size_t>(r.width) * r.height)
                            return;
                          throw InputError("the ray list lays out " + std::to_string(r.width) +
                                           "x" + std::to_string(r.height) +
                                           " pixels but holds " + std::to_string(r.rays.size()) +
                                           " rays");
                        }},
             imager);
}

bool pointPixels(const Imager& imager) {
  return std::visit(Overloaded{[](const Camera&) { return false; },
                               [](const PointSetImager& p) {
                                 return p.step_u_world == glm::vec3(0.0f) &&
                                        p.step_v_world == glm::vec3(0.0f);
                               },
                               [](const RayListImager&) { return true; }},
                    imager);
}

bool raysShareOrigin(const Imager& imager) {
  return std::visit(Overloaded{[](const Camera&) { return true; },
                               [](const PointSetImager&) { return true; },
                               [](const RayListImager&) { return false; }},
                    imager);
}

std::vector<glm::vec3> viewpoints(const Imager& imager) {
  return std::visit(
      Overloaded{[](const Camera& c) { return std::vector<glm::vec3>{c.position_world}; },
                 [](const PointSetImager& p) { return std::vector<glm::vec3>{p.origin_world}; },
                 [](const RayListImager& r) {
                   std::vector<glm::vec3> origins;
                   for (const PrimaryRay& ray : r.rays) origins.push_back(ray.origin);
                   const auto less = [](const glm::vec3& a, const glm::vec3& b) {
                     return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
                   };
                   std::sort(origins.begin(), origins.end(), less);
                   origins.erase(std::unique(origins.begin(), origins.end()), origins.end());
                   return origins;
                 }},
      imager);
}

const char* imagerKind(const Imager& imager) {
  return std::visit(Overloaded{[](const Camera&) { return "camera"; },
                               [](const PointSetImager&) { return "point_set"; },
                               [](const RayListImager&) { return "ray_list"; }},
                    imager);
}

PrimaryRays::PrimaryRays(const Imager& imager) : imager_(imager) {
  // A camera's frame, computed once for all its rays.
  if (const Camera* camera = cameraOf(imager)) pinholeRays_.emplace(*camera);
}

// Each kind's rays by overload: a kind without one does not compile.
PrimaryRay PrimaryRays::ray(int32_t x, int32_t y) const {
  return std::visit(
      Overloaded{[&](const Camera& c) -> PrimaryRay {
                   return {c.position_world, pinholeRays_->direction(x, y)};
                 },
                 [&](const PointSetImager& p) -> PrimaryRay {
                   const glm::vec3 target = p.points_world[static_cast<std::size_t>(y) * p.width + x];
                   return {p.origin_world, glm::normalize(target - p.origin_world)};
                 },
                 [&](const RayListImager& r) {
                   return r.rays[static_cast<std::size_t>(y) * r.width + x];
                 }},
      imager_);
}

PrimaryRay PrimaryRays::ray(int32_t x, int32_t y, glm::vec2 offset) const {
  return std::visit(
      Overloaded{[&](const Camera& c) -> PrimaryRay {
                   return {c.position_world, pinholeRays_->direction(x, y, offset)};
                 },
                 [&](const PointSetImager& p) -> PrimaryRay {
                   const glm::vec3 target =
                       p.points_world[static_cast<std::size_t>(y) * p.width + x] +
                       offset.x * p.step_u_world + offset.y * p.step_v_world;
                   return {p.origin_world, glm::normalize(target - p.origin_world)};
                 },
                 // A point sample: every offset is the pixel's one ray.
                 [&](const RayListImager& r) {
                   return r.rays[static_cast<std::size_t>(y) * r.width + x];
                 }},
      imager_);
}

PixelSteps::PixelSteps(const Imager& imager, float side, int32_t x, int32_t y) {
  std::visit(Overloaded{[&](const Camera& c) {
                          pinhole_ = true;
                          origin_ = c.position_world;
                          forward_ = c.forward();
                          // A lens's steps are the distorted pixel's own; a
                          // pinhole's the same everywhere.
                          const Camera::RaySteps steps = c.rayStepsAt(x, y);
                          stepX_ = steps.alongX * side;
                          stepY_ = steps.alongY * side;
                        },
                        [&](const PointSetImager& p) {
                          // The points' own spacing: the cell each point stands for.
                          stepX_ = p.step_u_world * side;
                          stepY_ = p.step_v_world * side;
                        },
                        [](const RayListImager&) {}},  // point samples: no steps
             imager);
}

FootprintSteps PixelSteps::at(const glm::vec3& x, const glm::vec3& n) const {
  return at(x, n, origin_);
}

FootprintSteps PixelSteps::at(const glm::vec3& x, const glm::vec3& n,
                              const glm::vec3& origin) const {
  if (!pinhole_) return {stepX_, stepY_};
  // The pinhole's ray differentials carried to the surface (footprint_kernel.md).
  const glm::vec3 toSurface = x - origin;
  return {physics::surfaceStepAcrossPixel(toSurface, forward_, stepX_, n),
          physics::surfaceStepAcrossPixel(toSurface, forward_, stepY_, n)};
}

PointSetImager gridOnPlanarMesh(const scene::Scene& scene, const std::string& meshName,
                                int32_t width, int32_t height, const glm::vec3& origin_world,
                                bool lastLegCounts) {
  if (width < 1 || height < 1) {
    throw InputError("the point grid on '" + meshName + "' needs at least 1 x 1 points (got " +
                     std::to_string(width) + " x " + std::to_string(height) + ")");
  }
  // The relay wall's plane fit and frame: one check that the node is planar.
  const RelayWall wall = relayWallOf(scene, meshName);
  PointSetImager grid;
  grid.width = width;
  grid.height = height;
  grid.origin_world = origin_world;
  grid.last_leg_counts = lastLegCounts;
  grid.step_u_world = wall.x_axis * (wall.width_m / static_cast<float>(width));
  // Rows run down the image: towards the wall's -y.
  grid.step_v_world = -wall.y_axis * (wall.height_m / static_cast<float>(height));
  grid.points_world.reserve(static_cast<std::size_t>(width) * height);
  for (int32_t j = 0; j < height; ++j) {
    for (int32_t i = 0; i < width; ++i) {
      grid.points_world.push_back(
          wall.at((static_cast<float>(i) + 0.5f) / static_cast<float>(width),
                  1.0f - (static_cast<float>(j) + 0.5f) / static_cast<float>(height)));
    }
  }
  return grid;
}

}  // namespace tofsim::capture
