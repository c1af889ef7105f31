#pragma once
// The reference's scattering delays (issue 41): at a vertex whose material
// has a delay kernel (physics::ResponseKernel), the light it scatters is,
// with probability `fraction`, delayed by a delay drawn from the kernel and
// re-emitted through its matrix; otherwise it leaves at once (a delay
// sampled per vertex, as in Jarabo et al. 2014, "A Framework for Transient
// Rendering"). Energy is kept path by path: the choice changes when the light
// arrives and in which channel, never how much of it is counted.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/util/Random.h"

namespace tofsim::reference {

/// Draws delays from one kernel: exponential -tau ln u; Gaussian N(mean,
/// sigma^2) truncated to t >= 0 (by rejection); table: the inverse CDF of its
/// piecewise-linear density.
class DelaySampler {
 public:
  /// Throws std::invalid_argument for a kernel outside its ranges
  /// (physics::responseTaps's rules).
  explicit DelaySampler(const physics::ResponseKernel& kernel);

  double fraction() const { return kernel_.fraction; }
  const glm::dmat3& reemission() const { return kernel_.reemission; }
  bool reemits() const { return kernel_.reemission != glm::dmat3(1.0); }
  /// A delay of the delayed share, seconds (>= 0).
  double sample(Pcg32& rng) const;

 private:
  double sampleTable(double u) const;

  physics::ResponseKernel kernel_;
  std::vector<double> cumulative_;  ///< Table: the area up to each point, normalised to 1
};

/// A path's weight from the camera to its current vertex: the product of the
/// continuation weights (diagonal, per channel) and the re-emission matrices
/// met on the way, in that order. Diagonal (the undelayed paths' arithmetic,
/// byte for byte) until a re-emission makes it a matrix.
class PathWeight {
 public:
  /// Light leaving the current vertex is scaled per channel by w first.
  void scale(const glm::dvec3& w);
  /// The light leaving the current vertex is re-emitted: out = m * in.
  void reemit(const glm::dmat3& m);
  /// The light `radiance` leaving the current vertex, seen at the camera.
  glm::dvec3 apply(const glm::dvec3& radiance) const;

 private:
  glm::dvec3 diagonal_{1.0};
  std::optional<glm::dmat3> matrix_;
};

/// What a path carries besides its geometry: its weight and the delays of
/// its vertices so far (seconds), and the re-emission of the light's own
/// surface (VertexDelays::atLight), which acts on the light before anything
/// else on the path does.
struct PathState {
  PathWeight weight;
  double delay_s = 0.0;
  std::optional<glm::dmat3> atLight;
  /// The light `radiance` from the light, reflected at the current vertex
  /// towards the viewer, seen at the camera.
  glm::dvec3 seen(const glm::dvec3& radiance) const {
    return weight.apply(atLight ? *atLight * radiance : radiance);
  }
};

/// The scene's delay kernels by base id (ir::materialResponses: id k is
/// kernels[k - 1], 0 instant) and the choice at a vertex.
class VertexDelays {
 public:
  explicit VertexDelays(const std::vector<physics::ResponseKernel>& kernels);

  bool any() const { return !samplers_.empty(); }
  bool delays(int32_t response) const { return response > 0; }
  /// A vertex of base kernel `response` (0: instant, no draw) scatters the
  /// path's light: with probability fraction it is delayed (state.delay_s
  /// grows by a sampled delay) and re-emitted (state.weight.reemit).
  void atVertex(int32_t response, Pcg32& rng, PathState& state) const;
  /// The light's own surface (base kernel `response`, 0: none; an NLOS
  /// laser spot on its relay wall) delays the light it sends: drawn once per
  /// path, for every vertex the path lights (its re-emission in
  /// state.atLight).
  void atLight(int32_t response, Pcg32& rng, PathState& state) const;

 private:
  std::vector<DelaySampler> samplers_;
};

}  // namespace tofsim::reference
