#include "tofsim/lidar/BeamBackscatter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tofsim/lidar/Echoes.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The antiderivative of exp(-2 sigma s) / s^2 (0 at infinity).
double antiderivative(double sigmaT, double s) {
  if (s == kInfinity) return 0.0;
  const double x = 2.0 * sigmaT * s;
  return -std::exp(-x) / s + (x > 0.0 ? 2.0 * sigmaT * -std::expint(-x) : 0.0);
}

// The medium per channel as the lidar sees it, and the range each bin
// covers: its edges from the overlap on, and the per-bin backscatter of a
// whole bin (power x the channels' mean of sigma_s p(pi) x the integral).
struct BackscatterBins {
  glm::dvec3 sigmaT{0.0}, weight{0.0};  // weight = power x sigma_s p(pi) / channels
  std::vector<double> edges_m;          // bins + 1 range edges, each >= the overlap
  std::vector<double> whole;            // a whole bin's light
  double legsEta = 2.0, start_m = 0.0, width_m = 1.0;

  bool grey = false;  // every channel alike (fog): one integral for the three

  double light(double a, double b) const {
    if (!(b > a)) return 0.0;
    if (grey) return 3.0 * weight[0] * backscatterIntegral(sigmaT[0], a, b);
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
      if (weight[c] != 0.0) sum += weight[c] * backscatterIntegral(sigmaT[c], a, b);
    }
    return sum;
  }
  // DirectWaveforms' bin of a surface at range r.
  double binOf(double r) const { return std::floor((legsEta * r - start_m) / width_m); }
};

BackscatterBins backscatterBins(const LidarSpec& spec, const capture::Medium& medium,
                                const TimeAxis& axis) {
  BackscatterBins b;
  b.legsEta = (axis.camera_unwarp ? 1.0 : 2.0) * axis.index_of_refraction;
  b.start_m = axis.start_m();
  b.width_m = axis.bin_width_m();
  const double overlap = spec.backscatter.overlap_m;
  const double p = spec.backscatter.phase_at_pi_per_sr > 0.0
                       ? spec.backscatter.phase_at_pi_per_sr
                       : physics::phaseFunction(medium.phase, medium.g, -1.0f);
  b.sigmaT = glm::dvec3(medium.sigmaT());
  b.weight = glm::dvec3(medium.sigma_s_per_m) * (spec.power_W * p / 3.0);
  b.grey = b.sigmaT.x == b.sigmaT.y && b.sigmaT.y == b.sigmaT.z && b.weight.x == b.weight.y &&
           b.weight.y == b.weight.z;
  b.edges_m.resize(static_cast<std::size_t>(axis.bins) + 1);
  for (int32_t k = 0; k <= axis.bins; ++k) {
    b.edges_m[k] = std::max(overlap, (b.start_m + k * b.width_m) / b.legsEta);
  }
  b.whole.resize(axis.bins);
  for (int32_t k = 0; k < axis.bins; ++k) b.whole[k] = b.light(b.edges_m[k], b.edges_m[k + 1]);
  return b;
}

// One beam: its rays' surfaces (into `surfaceBins`), and its backscatter
// added to `waveform` bin by bin with the share of the beam still in the
// medium (`cover`, bins + 1 values of scratch).
WaveformLoss addBeam(const LidarSpec& spec, const std::vector<BeamRay>& rays,
                     const WaveformScene& scene, const BackscatterBins& b, int32_t ring,
                     int32_t azimuth, float* waveform, int32_t* surfaceBins,
                     std::vector<double>& cover) {
  const auto bins = static_cast<int32_t>(b.whole.size());
  const double overlap = spec.backscatter.overlap_m;
  const BeamFrame frame = beamFrame(beamDirection(spec, ring, azimuth), spec.up_world);
  std::fill(cover.begin(), cover.end(), 0.0);
  WaveformLoss lost;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const glm::vec3 d = rayDirection(frame, rays[i].offset_rad);
    const std::optional<rays::SurfaceHit> hit = scene.rays->intersect(spec.position_world, d);
    const double D = hit && hit->distance_m > 0.0f ? double(hit->distance_m) : kInfinity;
    const double k = D == kInfinity ? double(bins) : b.binOf(D);
    surfaceBins[i] = D != kInfinity && k >= 0.0 && k < bins ? static_cast<int32_t>(k) : -1;
    const double share = rays[i].share;
    lost.before += share * b.light(overlap, std::min(D, b.edges_m.front()));
    if (k < 0.0) continue;
    // Whole bins [0, k): cover[0] += share, cover[k] -= share; then the bin
    // holding the surface up to it, or past the axis' end.
    const auto full = static_cast<int32_t>(std::min(k, double(bins)));
    cover[0] += share;
    cover[full] -= share;
    if (k < bins) {
      waveform[full] += static_cast<float>(share * b.light(b.edges_m[full], D));
    } else {
      lost.after += share * b.light(b.edges_m.back(), D);
    }
  }
  double share = 0.0;
  for (int32_t k = 0; k < bins; ++k) {
    share += cover[k];
    if (share > 0.0) waveform[k] += static_cast<float>(share * b.whole[k]);
  }
  return lost;
}

}  // namespace

double backscatterIntegral(double sigmaT, double a, double b) {
  if (!(b > a)) return 0.0;
  return antiderivative(sigmaT, b) - antiderivative(sigmaT, a);
}

BeamSurfaces addBackscatter(const LidarSpec& spec, const WaveformScene& scene,
                            const TimeAxis& axis, int threads, LidarWaveforms& waveforms) {
  const std::vector<BeamRay> rays = beamRays(spec.beam_rays, spec.divergence_rad, spec.profile);
  const int32_t azimuths = spec.azimuths();
  const auto beams = static_cast<std::size_t>(spec.channels()) * static_cast<std::size_t>(azimuths);
  BeamSurfaces surfaces{static_cast<int32_t>(rays.size()), {}};
  if (!scene.medium.scatters()) return surfaces;
  surfaces.bins.assign(beams * rays.size(), -1);
  const BackscatterBins b = backscatterBins(spec, scene.medium, axis);
  constexpr std::size_t kBlock = 256;
  std::vector<WaveformLoss> lost((beams + kBlock - 1) / kBlock);
  float* data = waveforms.volume.data();
  const std::size_t stride = waveforms.volume.pixelStride();
  parallelForBlocks(beams, kBlock, resolveThreads(threads), [&](std::size_t begin, std::size_t end) {
    std::vector<double> cover(b.whole.size() + 1);
    WaveformLoss& l = lost[begin / kBlock];
    for (std::size_t i = begin; i < end; ++i) {
      const WaveformLoss beam =
          addBeam(spec, rays, scene, b, static_cast<int32_t>(i / azimuths),
                  static_cast<int32_t>(i % azimuths), data + i * stride,
                  surfaces.bins.data() + i * rays.size(), cover);
      l.before += beam.before;
      l.after += beam.after;
    }
  });
  for (const WaveformLoss& l : lost) {  // in block order: the same sum for any thread count
    waveforms.lost.before += l.before;
    waveforms.lost.after += l.after;
  }
  return surfaces;
}

std::vector<uint8_t> fogReturnFlags(const LidarSpec& spec, const TransientVolume& waveforms,
                                    const BeamSurfaces& surfaces) {
  std::vector<uint8_t> flags;
  if (surfaces.bins.empty()) return flags;  // the medium does not scatter: none are fog's
  const int32_t azimuths = spec.azimuths();
  const auto R = static_cast<std::size_t>(surfaces.raysPerBeam);
  for (int32_t ring = 0; ring < spec.channels(); ++ring) {
    for (int32_t a = 0; a < azimuths; ++a) {
      const float* w = waveforms.data() + waveforms.index(ring, a, 0, 0);
      const int32_t* beam =
          surfaces.bins.data() + (static_cast<std::size_t>(ring) * azimuths + a) * R;
      for (const Echo& e : selectReturns(findEchoes(w, waveforms.axis(), spec.returns), spec.returns)) {
        const bool onSurface = std::any_of(beam, beam + R, [&](int32_t k) {
          return k >= e.first_bin && k <= e.last_bin;
        });
        flags.push_back(onSurface ? 0 : 1);
      }
    }
  }
  return flags;
}

}  // namespace tofsim::lidar
