#include "MergedSamples.h"

#include <algorithm>
#include <cmath>

#include "tofsim/ir/SampledPixels.h"

namespace tofsim::cpu {

void mergePixelSamples(const PixelSurface* samples, const unsigned char* lit, int n,
                       std::vector<PixelSurface>& out) {
  std::vector<std::vector<int>> groups;
  for (int s = 0; s < n * n; ++s) {
    if (!lit[s]) continue;
    auto group = std::find_if(groups.begin(), groups.end(), [&](const std::vector<int>& g) {
      const PixelSurface& first = samples[g.front()];
      return ir::onFlatSurface(first.x, first.n, samples[s].x, samples[s].n);
    });
    if (group == groups.end()) {
      groups.push_back({s});
    } else {
      group->push_back(s);
    }
  }
  for (const std::vector<int>& g : groups) {
    if (g.size() == 1) {
      out.push_back(samples[g.front()]);
      continue;
    }
    double cx = 0.0, cy = 0.0;
    int x0 = n, x1 = 0, y0 = n, y1 = 0;
    for (int s : g) {
      cx += s % n, cy += s / n;
      x0 = std::min(x0, s % n), x1 = std::max(x1, s % n);
      y0 = std::min(y0, s / n), y1 = std::max(y1, s / n);
    }
    cx /= static_cast<double>(g.size()), cy /= static_cast<double>(g.size());
    int nearest = g.front();
    double best = INFINITY;
    glm::vec3 brdf(0.0f);
    float weight = 0.0f;
    for (int s : g) {
      const double d = (s % n - cx) * (s % n - cx) + (s / n - cy) * (s / n - cy);
      if (d < best) best = d, nearest = s;
      brdf += samples[s].brdf;
      weight += samples[s].weight;
    }
    PixelSurface merged = samples[nearest];
    merged.brdf = brdf;
    merged.weight = weight;
    const float columns = static_cast<float>(x1 - x0 + 1), rows = static_cast<float>(y1 - y0 + 1);
    const float fill = std::sqrt(static_cast<float>(g.size()) / (columns * rows));
    merged.dxdu *= columns * fill;
    merged.dxdv *= rows * fill;
    out.push_back(merged);
  }
}

}  // namespace tofsim::cpu
