#include "GatherKernel.h"

#include <cmath>

#include "tofsim/physics/TransientPhysics.h"

namespace tofsim::cpu {

// target_clones: an AVX2 build and a baseline one of the same source, picked
// at load time. -ffp-contract=off (CMakeLists.txt) keeps fused multiply-adds
// out, and -fno-math-errno only lets sqrt vectorise, so both clones compute
// the same correctly rounded IEEE operations and give the same bytes.
__attribute__((target_clones("avx2", "default"))) void vplTerms(const PixelSurface& s,
                                                                const VplArrays& v,
                                                                std::size_t first, std::size_t n,
                                                                const GatherConstants& c,
                                                                VplTerms& terms) {
  const float* px = v.px.data() + first;
  const float* py = v.py.data() + first;
  const float* pz = v.pz.data() + first;
  const float* path = v.path.data() + first;
  const float* nx = v.nx.data() + first;
  const float* ny = v.ny.data() + first;
  const float* nz = v.nz.data() + first;
  const float* fr = v.fr.data() + first;
  const float* fg = v.fg.data() + first;
  const float* fb = v.fb.data() + first;
  const float offAxis_m = c.start_m - 2.0f * c.binWidth_m;  // a finite path for dark lanes
  for (std::size_t i = 0; i < n; ++i) {
    // The same steps as indirect_gather.comp, lane by lane.
    const float tx = s.x.x - px[i], ty = s.x.y - py[i], tz = s.x.z - pz[i];
    const float dist2 = tx * tx + ty * ty + tz * tz;
    const float dist = std::sqrt(dist2);
    const float dx = tx / dist, dy = ty / dist, dz = tz / dist;
    const float cosVpl = nx[i] * dx + ny[i] * dy + nz[i] * dz;
    const float cosX = -(s.n.x * dx + s.n.y * dy + s.n.z * dz);
    // & rather than &&: no branch, so the loop vectorises.
    const bool lit = (dist2 > 0.0f) & (cosVpl > 0.0f) & (cosX > 0.0f);
    const float g = physics::geometryTerm(cosVpl, cosX, dist2, c.geometryClamp);
    const float path_m = physics::vplPathLength(path[i], c.indexOfRefraction, dist, s.cameraPath_m);
    const int bin = physics::binOfPath(lit ? path_m : offAxis_m, c.start_m, c.binWidth_m);
    terms.bin[i] = lit ? bin : kNoLight;
    terms.r[i] = s.brdf.r * fr[i] * g;
    terms.g[i] = s.brdf.g * fg[i] * g;
    terms.b[i] = s.brdf.b * fb[i] * g;
    terms.dx[i] = dx, terms.dy[i] = dy, terms.dz[i] = dz, terms.dist[i] = dist;
  }
}

}  // namespace tofsim::cpu
