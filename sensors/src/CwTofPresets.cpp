#include "tofsim/sensors/CwTofPresets.h"

#include <array>

namespace tofsim::sensors {

namespace {

// --- kinect-v2: Microsoft Kinect for Xbox One, 9 raws ------------------------
// libfreenect2 decodes raw k of a frequency as the phase
// atan2(-sum m_k sin theta_k, sum m_k cos theta_k), theta_k = 2 pi k / 3: its
// raw k correlates at cos(phi + theta_k). tofsim's step n correlates at
// cos(phi - 2 pi n / N), so Kinect's raw k is step (3 - k) mod 3.
void applyKinectV2(CwTofParams& p) {
  p.frequencies_Hz = {80e6, 16e6, 120e6};
  p.phase_steps = 3;
  p.capture_order.clear();
  for (int32_t f = 0; f < 3; ++f) {
    for (int32_t k = 0; k < 3; ++k) p.capture_order.push_back({f, (3 - k) % 3});
  }
  p.taps = 2;
  p.adc_bits = 16;
  p.adc_offset_dn = 32768.0;
  p.max_depth_m = 6.0;
}
constexpr std::array<PresetValue, 9> kKinectV2Values{{
    {"frequencies",
     "[LF2] sub-images 0-2, 3-5, 6-8; the dealiasing multiplies the phases by 3, 15, 2: 80, 16, "
     "120 MHz (libfreenect2 #747)",
     nullptr},
    {"phase_steps", "[LF2] 3 phases per frequency, 0, 120, 240 deg (processMeasurementTriple)",
     nullptr},
    {"capture_order",
     "[LF2] the 9 raws in libfreenect2's order; its raw k (cos(phi + 2 pi k / 3)) is tofsim's "
     "step (3 - k) mod 3 (cos(phi - 2 pi n / 3)): [[0,0],[0,2],[0,1],[1,0],[1,2],[1,1],[2,0],"
     "[2,2],[2,1]]",
     nullptr},
    {"taps", nullptr,
     "signed int16 raws [LF2] read as the difference of two taps; the taps' gains and common "
     "mode are not published"},
    {"adc_bits",
     "[LF2] int16 raws, 32767 marks saturation: 16 bits with `adc_offset` 32768, DN - 32768 is "
     "libfreenect2's int16 (65535 DN = 32767, saturated)",
     nullptr},
    {"adc_offset", "[LF2] the int16 zero at 32768 DN (see adc_bits)", nullptr},
    {"adc_gain", nullptr, "electrons per DN are not published: the library default 1 DN / e-"},
    {"companding", nullptr,
     "the device maps 11-bit codes to int16 through a LUT (lut11to16) read from each device "
     "[LF2]: linear assumed (none)"},
    {"max_depth", "[FLAT] pipe/kinect_init.py max_depth 6 m (min_depth 0.5 m)", nullptr},
}};
constexpr std::array<const char*, 3> kKinectV2Sources{{
    "[LF2] OpenKinect/libfreenect2 @fd64c5d src/cpu_depth_packet_processor.cpp "
    "(decodePixelMeasurement, processMeasurementTriple), src/depth_packet_processor.cpp; issues "
    "#747, #821, #1057",
    "[FLAT] NVlabs/FLAT @56242b4 README.md, sim/kinect_spec.py, sim/tof_class.py, "
    "pipe/kinect_init.py",
    "[PAYNE14] Payne et al., ISSCC 2014, as listed at "
    "researching.cn/articles/OJ4df9f1b269a5cfd4/referenceandcitations",
}};

// --- azure-kinect-*: Azure Kinect DK depth modes -----------------------------
// The frequencies are not published [AK1807]: one assumed set for every mode.
void applyAzureFrequencies(CwTofParams& p) {
  p.frequencies_Hz = {320e6, 180e6, 100e6};
  p.phase_steps = 3;
}
// A mode differs from the others only by its range, in millimetres: a floating-point template
// argument needs C++20 support clang 14 (the fuzz build's compiler) does not have.
template <int MaxDepth_mm>
void applyAzureMode(CwTofParams& p) {
  applyAzureFrequencies(p);
  p.max_depth_m = MaxDepth_mm / 1000.0;
}
constexpr PresetValue kAzureFrequencies{
    "frequencies", nullptr,
    "not published (raws are not exposed [AKDOC]): 320, 180, 100 MHz, inside the 10-320 MHz "
    "range and averaging its 200 MHz [AK1807]; gcd 20 MHz, 7.49 m unambiguous, past every mode's "
    "range"};
constexpr PresetValue kAzureSteps{"phase_steps", nullptr,
                                  "not published: 3 per frequency (9 raws, as Kinect v2)"};
constexpr std::array<PresetValue, 3> kAkNfovUnbinnedValues{{
    kAzureFrequencies,
    kAzureSteps,
    {"max_depth", "[AKVIEW] NFOV unbinned 0.5-4.0 m (640 x 576 [AKDOC])", nullptr},
}};
constexpr std::array<PresetValue, 3> kAkNfov2x2Values{{
    kAzureFrequencies,
    kAzureSteps,
    {"max_depth", "[AKVIEW] NFOV 2x2 binned 0.5-5.8 m (320 x 288 [AKDOC])", nullptr},
}};
constexpr std::array<PresetValue, 3> kAkWfov2x2Values{{
    kAzureFrequencies,
    kAzureSteps,
    {"max_depth", "[AKVIEW] WFOV 2x2 binned 0.25-3.0 m (512 x 512 [AKDOC])", nullptr},
}};
constexpr std::array<PresetValue, 3> kAkWfovUnbinnedValues{{
    kAzureFrequencies,
    kAzureSteps,
    {"max_depth", "[AKVIEW] WFOV unbinned 0.25-2.5 m (1024 x 1024 at <= 15 fps [AKDOC])", nullptr},
}};
constexpr std::array<const char*, 4> kAzureSources{{
    "[AKDOC] learn.microsoft.com/en-us/azure/kinect-dk/depth-camera; mode enum: "
    "microsoft.github.io/Azure-Kinect-Sensor-SDK/master/"
    "namespace_microsoft_1_1_azure_1_1_kinect_1_1_sensor_ae1bee72789a1fe39e868e5b39ba62108.html",
    "[AKVIEW] microsoft/Azure-Kinect-Sensor-SDK @e70b954 tools/k4aviewer/"
    "k4astaticimageproperties.h",
    "[AKTYPES] microsoft/Azure-Kinect-Sensor-SDK include/k4a/k4atypes.h "
    "(k4a_calibration_model_type_t)",
    "[AK1807] github.com/microsoft/Azure-Kinect-Sensor-SDK/issues/1807 (also #980, #509)",
}};
// What every mode leaves to the camera, after its own mode line.
#define TOFSIM_AZURE_LEAVES                                                                    \
  " [AKDOC]; the image is the camera's; its Brown-Conrady lens (k1..k6, p1, p2 [AKTYPES]) is " \
  "the camera's too (camera.lens from the device's calibration); the depth engine is "         \
  "proprietary, so raws, taps and ADC stay the library's"

// --- pmd-generic: CamSim's PMD defaults --------------------------------------
void applyPmdGeneric(CwTofParams& p) {
  p.frequencies_Hz = {10e6};
  p.phase_steps = 4;
  p.taps = 2;
  p.modulation_contrast = 0.75;
  p.full_well_e = 100'000.0;
  p.integration_time_s = 1.0 / 60.0;
}
constexpr std::array<PresetValue, 6> kPmdGenericValues{{
    {"frequencies", "[CAMSIM] modulation frequency 10 MHz", nullptr},
    {"phase_steps", "[CAMSIM] 4 subframes, tau = i pi / 2", nullptr},
    {"taps", "[CAMSIM] A and B taps per subframe, output (A - B, A + B)", nullptr},
    {"modulation_contrast", "[CAMSIM] contrast 0.75", nullptr},
    {"full_well", "[CAMSIM] each tap clamped at max_electrons = 100 000", nullptr},
    {"integration_time", "[CAMSIM] exposure 1/60 s per subframe", nullptr},
}};
constexpr std::array<const char*, 1> kPmdGenericSources{{
    "[CAMSIM] marlam/camsim @1c731a2 libcamsim/simulator.hpp, simulator.cpp, "
    "simulation-pmd-dignums-fs.glsl, simulation-pmd-result-fs.glsl",
}};

const std::array<CwTofPreset, 6> kPresets{{
    {"kinect-v2",
     "Microsoft Kinect v2 (Kinect for Xbox One): 512 x 424 pixels [LF2], 70 deg horizontal field "
     "of view [FLAT], demodulation up to 130 MHz [PAYNE14]; the image and field of view are the "
     "camera's (camera.width, camera.height, camera.fov); FLAT's min_depth 0.5 m and "
     "unambiguous_dist 2083.333 mm [FLAT] are no keys (the unwrapping searches max_depth; the "
     "frequencies' common period is 18.74 m); the "
     "per-pixel P0 phase tables are a `delay_map`, FLAT's noise table a `noise_table`",
     applyKinectV2, kKinectV2Values, kKinectV2Sources, 512, 424},
    {"azure-kinect-nfov-unbinned",
     "Azure Kinect DK depth camera, NFOV unbinned, 640 x 576, <= 30 fps" TOFSIM_AZURE_LEAVES,
     applyAzureMode<4000>, kAkNfovUnbinnedValues, kAzureSources, 640, 576},
    {"azure-kinect-nfov-2x2",
     "Azure Kinect DK depth camera, NFOV 2x2 binned, 320 x 288, <= 30 fps" TOFSIM_AZURE_LEAVES,
     applyAzureMode<5800>, kAkNfov2x2Values, kAzureSources, 320, 288},
    {"azure-kinect-wfov-2x2",
     "Azure Kinect DK depth camera, WFOV 2x2 binned, 512 x 512, <= 30 fps" TOFSIM_AZURE_LEAVES,
     applyAzureMode<3000>, kAkWfov2x2Values, kAzureSources, 512, 512},
    {"azure-kinect-wfov-unbinned",
     "Azure Kinect DK depth camera, WFOV unbinned, 1024 x 1024, <= 15 fps" TOFSIM_AZURE_LEAVES,
     applyAzureMode<2500>, kAkWfovUnbinnedValues, kAzureSources, 1024, 1024},
    {"pmd-generic",
     "a generic PMD camera with CamSim's defaults [CAMSIM]: 12 um pixels, 880 nm, QE 0.8 (the "
     "radiometry keys), Gaussian shot noise (tofsim draws Poisson); the image is the camera's",
     applyPmdGeneric, kPmdGenericValues, kPmdGenericSources, 0, 0},
}};
#undef TOFSIM_AZURE_LEAVES

}  // namespace

std::span<const CwTofPreset> cwtofPresets() { return kPresets; }

const CwTofPreset* findCwTofPreset(std::string_view name) {
  return findPreset(cwtofPresets(), name);
}

}  // namespace tofsim::sensors
