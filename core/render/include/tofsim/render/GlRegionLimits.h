#pragma once
// What the GL backend's per-region media (issue 42's `media:`) can take. A
// leg's passage through the regions is found in the shaders by a brute-force
// loop over each region's triangles (shaders/medium_regions.glsl): fine for
// the small closed meshes regions are (a tank: 12 to a few hundred
// triangles), and bounded here, because llvmpipe silently ends an
// invocation's loops after 65535 trips in total (IndirectLight's
// kTripsPerDispatch): the indirect gather follows one VPL -> sample leg per
// pixel sample in one invocation, so the triangles a scene's regions may have
// shrink with render.pixel_samples. The config refuses more at
// media[i].region (apps/pipeline's takeMediumRegions), the backend for a
// library caller.

#include <cstddef>
#include <cstdint>

namespace tofsim::render {

/// Crossings of one leg's line with one region's surface a shader keeps (to
/// count a crossing through an edge or a vertex, which several triangles
/// report, once): a leg with more raises the gathers' guard (a located
/// failure, not lost light). A box's line crosses 2, 12 through two corners.
inline constexpr int kGlRegionCrossings = 16;

/// The most triangles the regions of one scene may have together on GL.
inline constexpr std::size_t kGlRegionTrianglesMax = 1024;

/// Loop trips of one leg's passage through `regions` regions of `triangles`
/// triangles in all: the region loop, the triangle loop and the duplicate
/// checks of a few crossings.
inline std::size_t glRegionTripsPerLeg(std::size_t regions, std::size_t triangles) {
  return 1 + regions + triangles + 4 * static_cast<std::size_t>(kGlRegionCrossings);
}

/// The most region triangles (all regions together) a render with
/// `pixelSamples` per side takes on GL: one VPL's legs to a pixel's N^2
/// samples within half of a dispatch's loop trips (the rest is the VPL loop,
/// the samples and the shadow rays), counting one region per 4 triangles (a
/// closed mesh has at least 4), and at most kGlRegionTrianglesMax.
inline std::size_t glRegionTriangleLimit(int32_t pixelSamples) {
  const std::size_t samples = static_cast<std::size_t>(pixelSamples) * pixelSamples;
  const std::size_t perLeg = 10000 / samples;  // half of IndirectLight's kTripsPerDispatch
  const std::size_t fixed = glRegionTripsPerLeg(0, 0);
  if (perLeg <= fixed) return 0;
  const std::size_t triangles = (perLeg - fixed) * 4 / 5;  // T + T / 4 trips
  return triangles < kGlRegionTrianglesMax ? triangles : kGlRegionTrianglesMax;
}

}  // namespace tofsim::render
