#pragma once
// A point or spot light, or a cosine emitter, emitting one impulse at t = 0.

#include <cstdint>

#include <glm/glm.hpp>

namespace tofsim::capture {

struct Light {
  /// Lambertian: a cosine emitter facing direction_world, intensity
  /// intensity_W_per_sr * max(0, cos) -- the spot a laser makes on a relay
  /// wall, seen from the hidden scene (a non-line-of-sight capture's light).
  enum class Type { Point, Spot, Lambertian };
  Type type = Type::Point;
  glm::vec3 position_world{0.0f};
  glm::vec3 direction_world{0.0f, 0.0f, -1.0f};  ///< unit; spot and Lambertian lights
  /// Spot: full intensity inside cone_half_angle_deg - cone_falloff_deg, a
  /// smooth (smoothstep) falloff to zero at cone_half_angle_deg.
  float cone_half_angle_deg = 30.0f;
  float cone_falloff_deg = 0.0f;
  /// Radiant intensity per channel (R, G, B), W/sr, of the impulse's energy:
  /// the transient volume integrates to radiance as if this were a CW source.
  glm::vec3 intensity_W_per_sr{1.0f};
  /// The scene material (index into scene::Scene::materials) of the surface
  /// the light stands on, -1 for none: an NLOS laser spot on its relay wall.
  /// Its scattering delay is every path's first (the response classes'
  /// start kernel, ir::responseStartOf; the reference samples it at the spot).
  int32_t surface_material = -1;

  /// Fraction of the intensity emitted towards `direction` (unit): 1 for point
  /// lights, the cone profile for spots, the cosine for Lambertian lights.
  float angularProfile(const glm::vec3& direction) const;

  /// The profile as the gathers take it (physics::lightProfile and
  /// lightArrival in shaders/transient_physics.glsl): its kind
  /// (physics::LIGHT_POINT...), unit axis and a spot's cone cosines.
  struct ProfileTerms {
    int kind = 0;
    glm::vec3 axis{0.0f, 0.0f, -1.0f};
    float cosOuter = 0.0f;
    float cosInner = 0.0f;
  };
  ProfileTerms profileTerms() const;
};

}  // namespace tofsim::capture
