#include "tofsim/sensors/CwTof.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kCwTofStreamTag = 0x4357;  // "CW"

/// Per pixel: the noise-free raw values (F * N) of a volume.
struct Correlator {
  const CwTofParams& p;
  const TimeAxis& axis;
  std::vector<double> table;  // (F, N, T): correlation of each render bin

  Correlator(const CwTofParams& params, const TimeAxis& a) : p(params), axis(a) {
    const int32_t N = p.phase_steps;
    for (double f : p.frequencies_Hz) {
      for (int32_t k = 0; k < N; ++k) {
        const double phi = 2.0 * M_PI * k / N;
        for (int32_t t = 0; t < axis.bins; ++t) {
          const double t0 = axis.binStart_s(t);
          table.push_back(binCorrelation(p.waveform, f, phi, t0, t0 + axis.bin_width_s));
        }
      }
    }
  }

  /// raw[f * N + k] = 0.5 (sum E + ambient) + 0.5 sum_t E_t rho_t(f, k).
  void raw(const std::vector<double>& signal, double ambient, std::vector<double>& out) const {
    const std::size_t T = signal.size();
    const std::size_t FN = p.frequencies_Hz.size() * p.phase_steps;
    double total = ambient;
    for (double e : signal) total += e;
    out.assign(FN, 0.5 * total);
    for (std::size_t j = 0; j < FN; ++j) {
      const double* rho = table.data() + j * T;
      double s = 0.0;
      for (std::size_t t = 0; t < T; ++t) s += signal[t] * rho[t];
      out[j] += 0.5 * s;
    }
  }

  /// Phases (F) and the first frequency's amplitude from raw values.
  double depth(const std::vector<double>& raw, std::vector<double>& phases, double& amplitude,
               double range) const {
    const auto F = static_cast<int32_t>(p.frequencies_Hz.size());
    phases.resize(F);
    for (int32_t f = 0; f < F; ++f) {
      double a = 0.0;
      phaseFromSteps(raw.data() + static_cast<std::size_t>(f) * p.phase_steps, p.phase_steps,
                     phases[f], a);
      if (f == 0) amplitude = a;
    }
    // Delay -> depth in the medium (c / eta), so a scene in water is not
    // reported as (eta - 1) x depth of multipath error.
    return unwrapDepth_m(phases, p.frequencies_Hz, range, axis.depthPerSecond_m_per_s());
  }
};

SensorOutput makeOutput(const std::string& name, SensorOutput::Kind kind,
                        std::vector<int64_t> shape, std::vector<float> data,
                        const std::string& unit, const std::string& description) {
  SensorOutput o;
  o.name = name;
  o.kind = kind;
  o.shape = std::move(shape);
  o.data = std::move(data);
  o.unit = unit;
  o.description = description;
  return o;
}

void addImage(std::vector<SensorOutput>& outs, const std::string& name, int32_t H, int32_t W,
              std::vector<float> data, const std::string& unit, const std::string& description,
              const std::string& colormap) {
  outs.push_back(
      makeOutput(name, SensorOutput::Kind::Image, {H, W}, std::move(data), unit, description));
  SensorOutput png = outs.back();
  png.kind = SensorOutput::Kind::ColorMappedImage;
  png.colormap = colormap;
  outs.push_back(std::move(png));
}
}  // namespace

std::vector<SensorOutput> runCwTof(const TransientVolume& volume, const CwTofParams& p,
                                   uint64_t seed, const CwTofReferences& refs) {
  TOFSIM_CHECK(!p.frequencies_Hz.empty() && p.phase_steps >= 3);
  for (double f : p.frequencies_Hz) TOFSIM_CHECK(f > 0.0);
  TOFSIM_CHECK(p.ambient_e >= 0.0 && p.read_noise_e >= 0.0 && p.max_depth_m >= 0.0);
  checkChannelSelection(p.common.channel, volume);
  const int32_t H = volume.height(), W = volume.width();
  const auto F = static_cast<int32_t>(p.frequencies_Hz.size());
  const int32_t N = p.phase_steps;
  const Image* gt = refs.groundTruthDepth_m;
  const TransientVolume* direct = refs.directOnly;
  if (gt && (gt->width != W || gt->height != H || gt->channels < 1)) {
    throw InputError("cwtof ground-truth depth is " + std::to_string(gt->width) + "x" +
                     std::to_string(gt->height) + ", the volume " + std::to_string(W) + "x" +
                     std::to_string(H));
  }
  if (direct && (direct->width() != W || direct->height() != H ||
                 direct->channels() != volume.channels() || direct->bins() != volume.bins())) {
    throw InputError("cwtof direct-only volume does not match the volume's shape");
  }
  const double range = unwrapRange_m(p, volume.axis().depthPerSecond_m_per_s());
  const Correlator correlator(p, volume.axis());
  const std::size_t HW = static_cast<std::size_t>(H) * W;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> raw(static_cast<std::size_t>(F) * N * HW), phase(F * HW);
  std::vector<float> depth(HW), amplitude(HW), mpiGt(HW, nan), mpiDirect(HW, nan);

  std::vector<double> signal, ideal, noisy, phases;
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * W + x;
      pixelSignal(volume, p.common, y, x, signal);
      correlator.raw(signal, p.ambient_e, ideal);
      Rng rng(seed, pixelStream(kCwTofStreamTag, pixel));
      noisy = ideal;
      for (double& v : noisy) {
        if (p.shot_noise) v = static_cast<double>(rng.poisson(std::max(0.0, v)));
        if (p.read_noise_e > 0.0) v += rng.normal(0.0, p.read_noise_e);
      }
      for (std::size_t j = 0; j < noisy.size(); ++j) {
        raw[j * HW + pixel] = static_cast<float>(noisy[j]);
      }
      double amp = 0.0;
      depth[pixel] = static_cast<float>(correlator.depth(noisy, phases, amp, range));
      amplitude[pixel] = static_cast<float>(amp);
      for (int32_t f = 0; f < F; ++f) phase[f * HW + pixel] = static_cast<float>(phases[f]);
      if (!gt && !direct) continue;
      // Multipath error of the noise-free measurement.
      const double clean = correlator.depth(ideal, phases, amp, range);
      if (gt) {
        const float truth = gt->at(y, x, 0);
        if (std::isfinite(truth) && truth > 0.0f) mpiGt[pixel] = static_cast<float>(clean - truth);
      }
      if (direct) {
        pixelSignal(*direct, p.common, y, x, signal);
        correlator.raw(signal, 0.0, ideal);
        const double directDepth = correlator.depth(ideal, phases, amp, range);
        if (amp > 0.0) mpiDirect[pixel] = static_cast<float>(clean - directDepth);
      }
    }
  }

  std::vector<SensorOutput> outs;
  outs.push_back(makeOutput("cwtof_raw", SensorOutput::Kind::Array, {F, N, H, W}, std::move(raw),
                            "photo-electrons",
                            "CW-ToF raw correlation images (frequency, phase step, y, x)"));
  outs.push_back(makeOutput("cwtof_phase", SensorOutput::Kind::Array, {F, H, W}, std::move(phase),
                            "rad", "CW-ToF wrapped phase per frequency, [0, 2 pi)"));
  addImage(outs, "cwtof_depth", H, W, std::move(depth), "m", "CW-ToF depth (unwrapped)",
           p.colormap);
  addImage(outs, "cwtof_amplitude", H, W, std::move(amplitude), "photo-electrons",
           "CW-ToF amplitude at the first frequency", p.colormap);
  if (gt) {
    addImage(outs, "cwtof_mpi_error", H, W, std::move(mpiGt), "m",
             "CW-ToF depth error against the ground truth (noise-free)", p.colormap);
  }
  if (direct) {
    addImage(outs, "cwtof_mpi_error_direct", H, W, std::move(mpiDirect), "m",
             "CW-ToF depth error against the direct-only depth (noise-free)", p.colormap);
  }
  return outs;
}

}  // namespace tofsim::sensors
