#pragma once
// render.indirect.merge_pixel_samples: a pixel's N x N samples gather the
// indirect light once per flat surface among them, not once each. The
// indirect light varies slowly across a surface (it is the direct light that
// has the sharp shadows, and it keeps every sample); what the samples of an
// edge pixel are for is which surfaces the pixel sees and how much of it each
// covers. So, as the RSM's sub-texels (ir::flatSurfaceGroups), the samples on
// one flat surface (ir::onFlatSurface with the group's first) become one:
// at the member nearest their centroid, with their summed weight and
// albedo / pi, its footprint steps their bounding box shrunk to their area.

#include <vector>

#include "GatherKernel.h"

namespace tofsim::cpu {

/// Appends to `out` the merged samples of one pixel's n x n samples
/// (row-major, `lit[s]`: sample s sees a surface; unlit ones are dropped), in
/// the order of each group's first sample. A group of one is its sample
/// unchanged.
void mergePixelSamples(const PixelSurface* samples, const unsigned char* lit, int n,
                       std::vector<PixelSurface>& out);

}  // namespace tofsim::cpu
