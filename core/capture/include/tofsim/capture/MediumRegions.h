#pragma once
// Per-region media (issue 42's `media:`): homogeneous media each inside a
// closed glTF mesh (scene::RegionMesh, an interface that no renderer draws).
// Outside every region light travels in vacuum (or the time axis' index);
// inside region r it is attenuated by exp(-sigma_t,r x length) and slowed to
// c / eta_r. Regions do not overlap nor nest (checked when the scene is
// configured), so a segment's passage is the sum over the regions of its
// lengths inside each. Directions are not refracted at a region's boundary
// (its index only sets the time along the legs inside it).
//
// A segment's lengths inside a region come from all the crossings of its
// line with the region's triangles, entering (direction . normal < 0) or
// leaving, walked in order; the triangles are tested one by one (a region is
// a tank or a box: tens of triangles, not a scene).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tofsim/capture/Medium.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::capture {

/// One `media:` entry: a homogeneous medium inside the closed mesh named
/// `region` (a glTF mesh or node name).
struct RegionMedium {
  std::string region;
  Medium medium;
  /// The region's index of refraction: light covers c / eta m/s inside it.
  double index_of_refraction = 1.0;
};

/// A stretch [t0_m, t1_m) of a ray inside region `region`.
struct RegionSpan {
  double t0_m = 0.0;
  double t1_m = 0.0;
  int32_t region = 0;
};

/// What a segment crosses: its optical depth per channel (sum of sigma_t x
/// length inside each region) and the path it adds to its time, as geometric
/// metres at the time axis' index: sum (eta_r / eta_axis - 1) x length inside.
struct RegionPassage {
  glm::dvec3 opticalDepth{0.0};
  double extraPath_m = 0.0;
  glm::dvec3 transmittance() const { return glm::exp(-opticalDepth); }
};

class MediumRegions {
 public:
  MediumRegions() = default;
  /// `media` joined with scene.regions by name (scene::takeRegionMesh put
  /// them there, in the same order); axisIndex: time.index_of_refraction.
  MediumRegions(const std::vector<RegionMedium>& media, const scene::Scene& scene,
                double axisIndex);

  bool empty() const { return regions_.empty(); }
  std::size_t size() const { return regions_.size(); }
  const RegionMedium& medium(int32_t region) const {
    return regions_[static_cast<std::size_t>(region)].params;
  }
  /// Whether some region scatters (sigma_s > 0 in a channel).
  bool scatters() const;

  /// The stretches of origin + t dir (unit dir), t in [0, length_m], inside
  /// regions, in order of t, into `out` (cleared).
  void spans(const glm::dvec3& origin, const glm::dvec3& dir, double length_m,
             std::vector<RegionSpan>& out) const;
  /// The segment a -> b's passage through the regions.
  RegionPassage passage(const glm::dvec3& a, const glm::dvec3& b) const;
  /// exp(-optical depth) of a -> b per channel, in float.
  glm::vec3 transmittance(const glm::vec3& a, const glm::vec3& b) const {
    return glm::vec3(passage(glm::dvec3(a), glm::dvec3(b)).transmittance());
  }
  /// The time's extra path of a -> b (RegionPassage::extraPath_m).
  double extraPath_m(const glm::vec3& a, const glm::vec3& b) const {
    return passage(glm::dvec3(a), glm::dvec3(b)).extraPath_m;
  }
  /// The extra path per metre inside region r: eta_r / eta_axis - 1.
  double delayPerMetre(int32_t region) const {
    return regions_[static_cast<std::size_t>(region)].delayPerMetre;
  }

 private:
  struct Region {
    RegionMedium params;
    std::vector<glm::dvec3> triangles;  ///< 3 per triangle, wound outwards
    glm::dvec3 lo{0.0}, hi{0.0};
    double delayPerMetre = 0.0;
  };
  // The stretches of the whole line origin + t dir inside region r, appended
  // to `out` unclipped.
  void lineSpans(const Region& r, int32_t index, const glm::dvec3& origin, const glm::dvec3& dir,
                 std::vector<RegionSpan>& out) const;
  std::vector<Region> regions_;
};

}  // namespace tofsim::capture
