#include "CpuIsm.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ParallelFor.h"
#include "tofsim/physics/ShaderRandom.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {

namespace {

constexpr float kEmpty = std::numeric_limits<float>::infinity();

/// cullHidden's arrays, from the batch's first VPL of the block on.
struct CullLanes {
  const float *tx, *ty, *tz, *bx, *by, *bz, *nx, *ny, *nz;
  const float* maps;        ///< the block's first VPL's map
  std::size_t mapStride;    ///< floats per VPL's maps
  int resolution;
  float scaleBias;          ///< 0.01 scene scale, as visible()
  glm::vec3 receiverNormal; ///< the pixel sample's normal (the bias's slope)
  float cosineOffset;       ///< its receiver cosine's offset (PixelSurface::cosineOffset)
};

// visible()'s steps lane by lane: paraboloidTexelOf with the VPL's basis
// read instead of built (basisAround gives the same floats either way), its
// products and sums in the order of glm's transpose(B) * d.
__attribute__((target_clones("avx2", "default"))) void cullLanes(const CullLanes& c,
                                                                 std::size_t n,
                                                                 VplTerms& __restrict terms) {
  const float* __restrict tx = c.tx;
  const float* __restrict ty = c.ty;
  const float* __restrict tz = c.tz;
  const float* __restrict bx = c.bx;
  const float* __restrict by = c.by;
  const float* __restrict bz = c.bz;
  const float* __restrict nx = c.nx;
  const float* __restrict ny = c.ny;
  const float* __restrict nz = c.nz;
  const float* __restrict maps = c.maps;
  const int r = c.resolution;
  const int stride = static_cast<int>(c.mapStride);
  const float rf = static_cast<float>(r), perTexel = 4.0f / static_cast<float>(r);
  const float scaleBias = c.scaleBias;
  const float rnx = c.receiverNormal.x, rny = c.receiverNormal.y, rnz = c.receiverNormal.z;
  const float cosineOffset = c.cosineOffset;
  for (std::size_t i = 0; i < n; ++i) {
    const float dx = terms.dx[i], dy = terms.dy[i], dz = terms.dz[i], dist = terms.dist[i];
    const float lx = tx[i] * dx + ty[i] * dy + tz[i] * dz;
    const float ly = bx[i] * dx + by[i] * dy + bz[i] * dz;
    const float lz = nx[i] * dx + ny[i] * dy + nz[i] * dz;
    const float den = 1.0f + std::max(lz, 0.0f);
    const float u = lx / den * 0.5f + 0.5f, v = ly / den * 0.5f + 0.5f;
    const int texelX = std::clamp(static_cast<int>(u * rf), 0, r - 1);
    const int texelY = std::clamp(static_cast<int>(v * rf), 0, r - 1);
    const float stored = maps[static_cast<int>(i) * stride + texelY * r + texelX];
    const float cosX = cosineOffset - (rnx * dx + rny * dy + rnz * dz);
    const float bias = physics::ismDepthBias(dist, cosX, perTexel, scaleBias);
    const bool hidden = !(dist - bias <= stored);
    terms.bin[i] = hidden ? kNoLight : terms.bin[i];
  }
}

}  // namespace

CpuIsm::CpuIsm(const scene::Scene& scene, const std::vector<ir::Vpl>& vpls,
               const capture::IndirectSettings& settings, uint64_t seed)
    : soup_(scene::buildTriangleSoup(scene)),
      settings_(settings),
      seed32_(static_cast<uint32_t>(seed ^ (seed >> 32))) {  // as IndirectLight's uSeed
  TOFSIM_CHECK(soup_.triangleCount() > 0);
  for (const ir::Vpl& v : vpls) {
    vplPosition_.emplace_back(v.positionPath);
    vplNormal_.emplace_back(v.normal);
    const glm::mat3 basis = physics::basisAround(glm::vec3(v.normal));
    tx_.push_back(basis[0].x), ty_.push_back(basis[0].y), tz_.push_back(basis[0].z);
    bx_.push_back(basis[1].x), by_.push_back(basis[1].y), bz_.push_back(basis[1].z);
    nx_.push_back(basis[2].x), ny_.push_back(basis[2].y), nz_.push_back(basis[2].z);
  }
  // The level layout of IndirectLight: finest first, halving (rounded up) to 1x1.
  for (int size = settings_.ism_resolution;; size = (size + 1) / 2) {
    levelOffsets_.push_back(floatsPerVpl_);
    levelSizes_.push_back(size);
    floatsPerVpl_ += static_cast<std::size_t>(size) * size;
    if (size == 1 || !settings_.ism_pull_push) break;
  }
}

std::size_t CpuIsm::fixedBytes() const {
  return soup_.corners.size() * sizeof(glm::vec4) + soup_.areaCdf.size() * sizeof(float) +
         vplPosition_.size() * (2 * sizeof(glm::vec3) + 9 * sizeof(float));
}

void CpuIsm::allocate(std::size_t vplsPerBatch) {
  maps_.assign(vplsPerBatch * floatsPerVpl_, kEmpty);
}

glm::vec3 CpuIsm::samplePoint(uint32_t h0, uint32_t h1, uint32_t h2) const {
  // sampleSurface in scene_geometry.glsl: the first triangle whose CDF exceeds r0.
  const float r0 = physics::unitFloat(h0);
  const std::size_t tri = std::min<std::size_t>(
      std::upper_bound(soup_.areaCdf.begin(), soup_.areaCdf.end(), r0) - soup_.areaCdf.begin(),
      soup_.triangleCount() - 1);
  const glm::vec4* c = &soup_.corners[3 * tri];
  return physics::pointOnTriangle(glm::vec3(c[0]), glm::vec3(c[1]), glm::vec3(c[2]),
                                  physics::unitFloat(h1), physics::unitFloat(h2));
}

void CpuIsm::splat(std::size_t vpl, float* map) const {
  const int r = settings_.ism_resolution;
  const auto index = static_cast<uint32_t>(vpl);
  const auto points = static_cast<uint32_t>(capture::ismPointsPerVpl(settings_));
  for (uint32_t j = 0; j < points; ++j) {
    // The steps of ism_splat.comp.
    const uint32_t h0 = physics::hash3(seed32_, index, j);
    const uint32_t h1 = physics::pcgHash(h0), h2 = physics::pcgHash(h1);
    const glm::vec3 d = samplePoint(h0, h1, h2) - vplPosition_[vpl];
    const float dist = glm::length(d);
    if (dist < 1e-6f || glm::dot(d, vplNormal_[vpl]) <= 0.0f) continue;
    const glm::ivec2 t = physics::paraboloidTexelOf(vplNormal_[vpl], d / dist, r);
    float& texel = map[t.y * r + t.x];
    texel = std::min(texel, dist);
  }
}

void CpuIsm::pullPush(float* map) const {
  const std::size_t levels = levelSizes_.size();
  for (std::size_t k = 0; k + 1 < levels; ++k) {  // pull: ism_pull.comp
    const int fine = levelSizes_[k], coarse = levelSizes_[k + 1];
    const float* f = map + levelOffsets_[k];
    float* c = map + levelOffsets_[k + 1];
    for (int cy = 0; cy < coarse; ++cy) {
      for (int cx = 0; cx < coarse; ++cx) {
        float sum = 0.0f;
        int count = 0;
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            const int fx = 2 * cx + dx, fy = 2 * cy + dy;
            if (fx >= fine || fy >= fine) continue;
            const float value = f[fy * fine + fx];
            if (!std::isinf(value)) sum += value, ++count;
          }
        }
        c[cy * coarse + cx] = count > 0 ? sum / static_cast<float>(count) : kEmpty;
      }
    }
  }
  for (std::size_t k = levels - 1; k-- > 0;) {  // push: ism_push.comp
    const int fine = levelSizes_[k], coarse = levelSizes_[k + 1];
    float* f = map + levelOffsets_[k];
    const float* c = map + levelOffsets_[k + 1];
    for (int t = 0; t < fine * fine; ++t) {
      if (std::isinf(f[t])) f[t] = c[(t / fine / 2) * coarse + (t % fine) / 2];
    }
  }
}

void CpuIsm::build(std::size_t firstVpl, std::size_t count, int threads) {
  TOFSIM_CHECK(count * floatsPerVpl_ <= maps_.size());
  firstVpl_ = firstVpl;
  builtCount_ = count;
  parallelFor(count, threads, [&](std::size_t i) {
    float* map = &maps_[i * floatsPerVpl_];
    std::fill_n(map, floatsPerVpl_, kEmpty);
    // A medium VPL (zero normal) has no hemisphere to map: its map stays
    // empty, passes every lane, and CpuBackend tests it exactly.
    if (vplNormal_[firstVpl + i] == glm::vec3(0.0f)) return;
    splat(firstVpl + i, map);
    pullPush(map);
  });
}

bool CpuIsm::visible(std::size_t vpl, const glm::vec3& d, float dist,
                     const glm::vec3& receiverNormal, float receiverCosineOffset,
                     float sceneScale_m) const {
  // The ISM branch of visible() in indirect_gather.comp.
  const int r = settings_.ism_resolution;
  const glm::ivec2 t = physics::paraboloidTexelOf(vplNormal_[vpl], d, r);
  const float stored = map(vpl)[t.y * r + t.x];
  const float cosX = receiverCosineOffset -
                     (receiverNormal.x * d.x + receiverNormal.y * d.y + receiverNormal.z * d.z);
  const float bias =
      physics::ismDepthBias(dist, cosX, 4.0f / static_cast<float>(r), 0.01f * sceneScale_m);
  return dist - bias <= stored;
}

void CpuIsm::cullHidden(std::size_t first, std::size_t n, float sceneScale_m,
                        const glm::vec3& receiverNormal, float receiverCosineOffset,
                        VplTerms& terms) const {
  TOFSIM_CHECK(first >= firstVpl_ && first + n <= firstVpl_ + builtCount_);
  const CullLanes lanes{tx_.data() + first,   ty_.data() + first, tz_.data() + first,
                        bx_.data() + first,   by_.data() + first, bz_.data() + first,
                        nx_.data() + first,   ny_.data() + first, nz_.data() + first,
                        map(first),           floatsPerVpl_,      settings_.ism_resolution,
                        0.01f * sceneScale_m, receiverNormal,     receiverCosineOffset};
  cullLanes(lanes, n, terms);
}

}  // namespace tofsim::cpu
