// VPL temporal banding (issue 14, part 3), measured. Each VPL is a point with
// one path length, so few VPLs put the indirect light into stripes in time;
// render.indirect.vpl_footprint spreads each VPL over its RSM texel's patch.
//
// Scene: the Cornell box demo's camera, light and time axis (1.5 m from the
// lens, 640 bins of 10 ps) at a small image, CPU backend, exact visibility,
// geometry term clamp 100 /m^2, pixel footprint on; indirect volume only.
// Reference: the same render with a 256^2 RSM and vpl_footprint true.
//
// Metric. Per pixel p, h_p(t) = the indirect histogram summed over R, G, B;
// H_p(f) its DFT (zero-padded to 1024 bins). HF_c(x) = sum over |f| > f_c of
// |X(f)|^2, the energy above the cut-off f_c. For a render N against the
// reference R:
//   banding ratio  beta_c = sum_p HF_c(h_N,p) / sum_p HF_c(h_R,p)
//     (the high-frequency energy relative to the 256^2 render's; 1 = none added)
//   banding level  eps_c  = sqrt(sum_p HF_c(h_N,p - h_R,p) / sum_p sum_t h_R,p(t)^2)
//     (RMS of the difference's high-frequency part relative to the reference's RMS)
//   low-pass error lp_c   = the same with |f| <= f_c (VPL discretisation, not banding)
// Cut-offs given as the period 1 / f_c.
// Usage: tofsim_vpl_banding [side=32] [reference_rsm=256]
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/volume/PhysicalConstants.h"

#include "../BenchArgs.h"

namespace {

using namespace tofsim;
using Spectrum = std::vector<std::complex<double>>;

constexpr std::size_t kFftSize = 1024;
constexpr double kBin_s = 10e-12;
const double kPeriods_ps[] = {1000.0, 500.0, 200.0, 100.0};

void fft(Spectrum& a) {  // iterative radix 2, in place
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> w = std::polar(1.0, -2.0 * M_PI / static_cast<double>(len));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> wk = 1.0;
      for (std::size_t k = 0; k < len / 2; ++k, wk *= w) {
        const auto u = a[i + k], v = a[i + k + len / 2] * wk;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
      }
    }
  }
}

// Per pixel, the spectrum of the channel-summed histogram.
std::vector<Spectrum> spectra(const TransientVolume& v) {
  std::vector<Spectrum> out;
  for (int y = 0; y < v.height(); ++y)
    for (int x = 0; x < v.width(); ++x) {
      Spectrum s(kFftSize, 0.0);
      for (int t = 0; t < v.bins(); ++t)
        s[t] = double(v.at(y, x, t, 0)) + v.at(y, x, t, 1) + v.at(y, x, t, 2);
      fft(s);
      out.push_back(std::move(s));
    }
  return out;
}

bool above(std::size_t k, double period_ps) {  // |f_k| > 1 / period
  const std::size_t m = std::min(k, kFftSize - k);
  return m / (kFftSize * kBin_s) > 1.0 / (period_ps * 1e-12);
}

struct Render {
  std::vector<Spectrum> spectra;
  double seconds;
  std::size_t vpls;
};

Render renderIndirect(capture::RenderJob job, int rsm, bool vplFootprint) {
  job.settings.indirect.rsm_resolution = rsm;
  job.settings.indirect.vpl_footprint = vplFootprint;
  capture::VolumeCollector out(job.camera().width, job.camera().height, job.settings.time, 3);
  const auto start = std::chrono::steady_clock::now();
  const capture::RenderResult r =
      ir::IrRenderer(std::make_unique<cpu::CpuBackend>()).render(job, out);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {spectra(out.indirect), s, r.vpls};
}

void printRow(const char* name, int rsm, const Render& n, const Render& ref) {
  double refEnergy = 0.0;  // sum_p sum_t h^2 = sum_p sum_f |H|^2 / size (Parseval)
  for (const Spectrum& s : ref.spectra)
    for (const auto& z : s) refEnergy += std::norm(z);
  std::printf("| %d^2, %s | %zu | %.1f |", rsm, name, n.vpls, n.seconds);
  for (double period : kPeriods_ps) {
    double hfN = 0.0, hfR = 0.0, hfD = 0.0, lpD = 0.0;
    for (std::size_t p = 0; p < ref.spectra.size(); ++p)
      for (std::size_t k = 0; k < kFftSize; ++k) {
        const double d = std::norm(n.spectra[p][k] - ref.spectra[p][k]);
        if (above(k, period)) {
          hfN += std::norm(n.spectra[p][k]);
          hfR += std::norm(ref.spectra[p][k]);
          hfD += d;
        } else {
          lpD += d;
        }
      }
    std::printf(" %.2f / %.4f / %.4f |", hfN / hfR, std::sqrt(hfD / refEnergy),
                std::sqrt(lpD / refEnergy));
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int side = bench::arg(argc, argv, 1, 32);
  const int referenceRsm = bench::arg(argc, argv, 2, 256);
  const scene::Scene box = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  capture::RenderJob job = test::cornellBoxJob(box, side, 640, kBin_s * kSpeedOfLight_m_per_s);
  job.settings.indirect.visibility = capture::Visibility::Exact;
  const Render ref = renderIndirect(job, referenceRsm, true);
  std::printf(
      "Cornell box %dx%d, 640 bins of 10 ps from 1.5 m, CPU backend, exact visibility, "
      "clamp 100; reference: RSM %d^2, vpl_footprint true (%zu VPLs, %.1f s)\n\n",
      side, side, referenceRsm, ref.vpls, ref.seconds);
  std::printf(
      "cells: beta (HF energy / reference's) / eps (HF of the difference, relative RMS) / "
      "low-pass error (relative RMS)\n\n| RSM, vpl_footprint | VPLs | seconds |");
  for (double period : kPeriods_ps) std::printf(" period < %.0f ps |", period);
  std::printf("\n|---|---|---|---|---|---|---|\n");
  for (int rsm : {32, 64, 128}) {
    printRow("true", rsm, renderIndirect(job, rsm, true), ref);
    printRow("false", rsm, renderIndirect(job, rsm, false), ref);
  }
  printRow("false", referenceRsm, renderIndirect(job, referenceRsm, false), ref);
  return 0;
}
