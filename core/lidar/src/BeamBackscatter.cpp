#include "tofsim/lidar/BeamBackscatter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tofsim/lidar/Echoes.h"
#include "tofsim/lidar/ScanGrid.h"
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

}  // namespace

BackscatterLight::BackscatterLight(const LidarSpec& spec, const capture::Medium& medium,
                                   const TimeAxis& axis)
    : spec_(spec) {
  if (spec.scan == ScanPattern::Zones) {
    field_sr_ = fieldSolidAngle_sr(spec);
  } else {
    beamRays_ = beamRays(spec.beam_rays, spec.divergence_rad, spec.profile);
  }
  legsEta_ = (axis.camera_unwarp ? 1.0 : 2.0) * axis.index_of_refraction;
  start_m_ = axis.start_m();
  width_m_ = axis.bin_width_m();
  const double overlap = spec.backscatter.overlap_m;
  const double p = spec.backscatter.phase_at_pi_per_sr > 0.0
                       ? spec.backscatter.phase_at_pi_per_sr
                       : physics::phaseFunction(medium.phase, medium.g, -1.0f);
  sigmaT_ = glm::dvec3(medium.sigmaT());
  weight_ = glm::dvec3(medium.sigma_s_per_m) * (spec.power_W * p / 3.0);
  grey_ = sigmaT_.x == sigmaT_.y && sigmaT_.y == sigmaT_.z && weight_.x == weight_.y &&
          weight_.y == weight_.z;
  edges_m_.resize(static_cast<std::size_t>(axis.bins) + 1);
  for (int32_t k = 0; k <= axis.bins; ++k) {
    edges_m_[k] = std::max(overlap, (start_m_ + k * width_m_) / legsEta_);
  }
  whole_.resize(axis.bins);
  for (int32_t k = 0; k < axis.bins; ++k) whole_[k] = light(edges_m_[k], edges_m_[k + 1]);
}

int32_t BackscatterLight::raysPerBeam() const {
  return spec_.scan == ScanPattern::Zones ? spec_.grid.zone_rays * spec_.grid.zone_rays
                                          : static_cast<int32_t>(beamRays_.size());
}

double BackscatterLight::light(double a, double b) const {
  if (!(b > a)) return 0.0;
  if (grey_) return 3.0 * weight_[0] * backscatterIntegral(sigmaT_[0], a, b);
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    if (weight_[c] != 0.0) sum += weight_[c] * backscatterIntegral(sigmaT_[c], a, b);
  }
  return sum;
}

double BackscatterLight::binOf(double r) const {
  return std::floor((legsEta_ * r - start_m_) / width_m_);
}

// One beam: its rays' surfaces (into `surfaceBins`), and its backscatter
// added to `waveform` bin by bin with the share of the beam still in the
// medium (`cover`).
WaveformLoss BackscatterLight::addBeam(const rays::RayScene& scene, int32_t ring, int32_t azimuth,
                                       float* waveform, int32_t* surfaceBins) const {
  const std::vector<BeamRay> zone =
      beamRays_.empty() ? zoneRays(spec_, ring, azimuth, field_sr_) : std::vector<BeamRay>{};
  const std::vector<BeamRay>& rays = beamRays_.empty() ? zone : beamRays_;
  const auto bins = static_cast<int32_t>(whole_.size());
  const double overlap = spec_.backscatter.overlap_m;
  const BeamFrame frame = beamFrame(beamDirection(spec_, ring, azimuth), spec_.up_world);
  std::vector<double> cover(whole_.size() + 1, 0.0);
  WaveformLoss lost;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const glm::vec3 d = rayDirection(frame, rays[i].offset_rad);
    const std::optional<rays::SurfaceHit> hit = scene.intersect(spec_.position_world, d);
    const double D = hit && hit->distance_m > 0.0f ? double(hit->distance_m) : kInfinity;
    const double k = D == kInfinity ? double(bins) : binOf(D);
    surfaceBins[i] = D != kInfinity && k >= 0.0 && k < bins ? static_cast<int32_t>(k) : -1;
    const double share = rays[i].share;
    lost.before += share * light(overlap, std::min(D, edges_m_.front()));
    if (k < 0.0) continue;
    // Whole bins [0, k): cover[0] += share, cover[k] -= share; then the bin
    // holding the surface up to it, or past the axis' end.
    const auto full = static_cast<int32_t>(std::min(k, double(bins)));
    cover[0] += share;
    cover[full] -= share;
    if (k < bins) {
      waveform[full] += static_cast<float>(share * light(edges_m_[full], D));
    } else {
      lost.after += share * light(edges_m_.back(), D);
    }
  }
  double share = 0.0;
  for (int32_t k = 0; k < bins; ++k) {
    share += cover[k];
    if (share > 0.0) waveform[k] += static_cast<float>(share * whole_[k]);
  }
  return lost;
}

double backscatterIntegral(double sigmaT, double a, double b) {
  if (!(b > a)) return 0.0;
  return antiderivative(sigmaT, b) - antiderivative(sigmaT, a);
}

BeamSurfaces addBackscatter(const LidarSpec& spec, const WaveformScene& scene,
                            const TimeAxis& axis, int threads, LidarWaveforms& waveforms) {
  if (!scene.medium.scatters()) return {};
  const BackscatterLight light(spec, scene.medium, axis);
  const int32_t azimuths = spec.azimuths();
  const auto beams = static_cast<std::size_t>(spec.channels()) * static_cast<std::size_t>(azimuths);
  const auto R = static_cast<std::size_t>(light.raysPerBeam());
  BeamSurfaces surfaces{light.raysPerBeam(), std::vector<int32_t>(beams * R, -1)};
  std::vector<WaveformLoss> lost((beams + kBackscatterBlock - 1) / kBackscatterBlock);
  float* data = waveforms.volume.data();
  const std::size_t stride = waveforms.volume.pixelStride();
  parallelForBlocks(beams, kBackscatterBlock, resolveThreads(threads),
                    [&](std::size_t begin, std::size_t end) {
                      WaveformLoss& l = lost[begin / kBackscatterBlock];
                      for (std::size_t i = begin; i < end; ++i) {
                        const WaveformLoss beam = light.addBeam(
                            *scene.rays, static_cast<int32_t>(i / azimuths),
                            static_cast<int32_t>(i % azimuths), data + i * stride,
                            surfaces.bins.data() + i * R);
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
