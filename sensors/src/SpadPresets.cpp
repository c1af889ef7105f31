#include "tofsim/sensors/SpadPresets.h"

#include <array>

namespace tofsim::sensors {

namespace {

// --- nlos-gated-spad: Polimi fast-gated single-pixel SPAD + PicoHarp 300 ----
void applyNlosGated(SpadParams& p) {
  p.mode = SpadMode::Synchronous;
  p.bins.bin_width_s = 4e-12;
  p.dead_time_s = 95e-9;
  p.jitter_fwhm_s = 50e-12;
  p.cycles = 800'000;
  p.pde = 0.3;
}
constexpr std::array<SpadPresetValue, 6> kNlosGatedValues{{
    {"mode", "[PH300] TCSPC: one start-stop time per laser sync (first photon)", nullptr},
    {"bin_width", "[PH300] PicoHarp 300 base resolution 4 ps", nullptr},
    {"dead_time",
     "[PH300] TCSPC dead time 95 ns (after each detection: the cycles it spans are lost)", nullptr},
    {"jitter_fwhm",
     "[MH150 p.10] SPAD jitter 50-500 ps FWHM: the lower end; [RENNA20] < 50 ps FWHM for the "
     "fast-gated array",
     nullptr},
    {"cycles", nullptr, "10 ms at the 80 MHz maximum repetition rate [BUTT14]"},
    {"pde", nullptr, "no published PDE in the sources: the library default"},
}};
constexpr std::array<const char*, 4> kNlosGatedSources{{
    "[PH300] tcspc.com/doku.php/glossary:t2-mode",
    "[MH150] easymanua.ls/picoquant/multiharp-150/manual?p=70 and ?p=10",
    "[BUTT14] Rev. Sci. Instrum. 85, 083114 (scholar.archive.org/work/mhkqqcijonaspeelevybh7x5le)",
    "[RENNA20] mdpi.com/2410-390X/4/2/14",
}};

// --- spad512s: Pi Imaging 512 x 512 gated SPAD array -------------------------
void applySpad512s(SpadParams& p) {
  p.mode = SpadMode::Synchronous;
  p.bins.bin_width_s = 17e-12;
  p.pde = 0.5;
  p.dark_count_rate_per_s = 25.0;
  p.cycles = 100'000;
  p.pulse_fwhm_s = 30e-12;
  p.jitter_fwhm_s = 100e-12;
}
// Timing: Pi Imaging publishes no jitter and the laser is not part of the
// array, but 0 for both would make a sharper histogram than any real capture:
// both are assumed, within the published ranges, and say so.
constexpr std::array<SpadPresetValue, 7> kSpad512sValues{{
    {"mode", nullptr,
     "gated 1-bit frames are not modelled: the histogram a gate sweep samples, as first-photon "
     "counts"},
    {"bin_width", "[SPAD512S] gate shift 17 ps (the sweep's step, taken as the bin)", nullptr},
    {"pde", "[SPAD512S] PDP > 50 % at 520 nm", nullptr},
    {"dark_count_rate", "[SPAD512S] DCR < 25 cps typical", nullptr},
    {"cycles", nullptr, "1 s of 1-bit frames at 100 kfps [SPAD512S], one pulse per frame"},
    {"pulse_fwhm", nullptr,
     "the laser's, not the array's: a 30 ps FWHM picosecond laser, y-tal's default [TAL13]; set "
     "your laser's"},
    {"jitter_fwhm", nullptr,
     "not published for the SPAD512S: 100 ps FWHM, inside SPADs' 50-500 ps FWHM [MH150 p.10]"},
}};
constexpr std::array<const char*, 3> kSpad512sSources{{
    "[SPAD512S] axiomoptics.com/products/spad512s",
    "[TAL13] github.com/diegoroyo/tal/pull/13, tal/noise_simulation/noise_defaults.yaml",
    "[MH150] easymanua.ls/picoquant/multiharp-150/manual?p=70 and ?p=10",
}};

// --- flash-lidar-fbk256: FBK 256 x 256 flash-lidar SPAD imager --------------
void applyFlashLidar(SpadParams& p) {
  p.mode = SpadMode::Synchronous;
  p.bins.bin_width_s = 250e-12;
  p.pde = 0.28;
  p.cycles = 10'000;
}
constexpr std::array<SpadPresetValue, 4> kFlashLidarValues{{
    {"mode", "[FBK256] first-event detection", nullptr},
    {"bin_width", "[FBK256] 250 ps bins (up to 380 m)", nullptr},
    {"pde", nullptr,
     "FBK256's PDE is not public: Sony IMX611's 28 % [IMX611], a smartphone dToF SPAD"},
    {"cycles", nullptr, "the library default"},
}};
constexpr std::array<const char*, 2> kFlashLidarSources{{
    "[FBK256] imagesensors.org/papers/10.60928/brmo-wf6b",
    "[IMX611] fareastgizmos.com/featured/"
    "sony-semiconductor-solutions-announces-spad-depth-sensor-for-smartphones-with-high-accuracy-"
    "distance-measurement-performance.php",
}};

// No image size is checked (0, 0): a scanned single pixel, arrays often
// rendered cropped; the device line names their size.
const std::array<SpadPreset, 3> kPresets{{
    {"nlos-gated-spad",
     "single-pixel fast-gated SPAD (Polimi) with a PicoHarp 300 TCSPC, as in NLOS captures; the "
     "gate (110 ps transitions [BUTT14]) depends on the scene: set gate_start and gate_width",
     applyNlosGated, kNlosGatedValues, kNlosGatedSources, 0, 0},
    {"spad512s",
     "Pi Imaging SPAD512S, 512 x 512 gated SPAD array (0 e- read noise, 6 ns gate [SPAD512S]); "
     "the resolution is the camera's",
     applySpad512s, kSpad512sValues, kSpad512sSources, 0, 0},
    {"flash-lidar-fbk256",
     "FBK 256 x 256 flash-lidar SPAD imager with first- or last-event TDCs [FBK256]; the window "
     "(bins) is the render's",
     applyFlashLidar, kFlashLidarValues, kFlashLidarSources, 0, 0},
}};

}  // namespace

std::span<const SpadPreset> spadPresets() { return kPresets; }

const SpadPreset* findSpadPreset(std::string_view name) { return findPreset(spadPresets(), name); }

}  // namespace tofsim::sensors
