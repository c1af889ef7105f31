#include "tofsim/config/LidarPresets.h"

#include <yaml-cpp/yaml.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "LidarSection.h"
#include "ShortestNumber.h"

namespace tofsim::config {

namespace {

using sensors::PresetValue;

void evenChannels(LidarConfig& c, int32_t count, double min_deg, double max_deg) {
  c.channel_count = count;
  c.channel_min_deg = min_deg;
  c.channel_max_deg = max_deg;
  c.spec.elevations_deg.clear();
  for (int32_t i = 0; i < count; ++i) {
    c.spec.elevations_deg.push_back(min_deg + (max_deg - min_deg) * double(i) / double(count - 1));
  }
}

// --- spinning-16: a 16-channel spinning lidar, VLP-16 class -----------------
void applySpinning16(LidarDefaults& d) {
  lidar::LidarSpec& s = d.lidar.spec;
  s.scan = lidar::ScanPattern::Spinning;
  evenChannels(d.lidar, 16, -15.0, 15.0);
  s.azimuth_step_deg = 0.2;
  d.lidar.rotation_rate_Hz = 10.0;
  s.divergence_rad = 3e-3;
  s.profile = lidar::BeamProfile::Gaussian;
  s.returns.mode = lidar::ReturnMode::Dual;
  s.returns.max = 2;
}
constexpr std::array<PresetValue, 7> kSpinning16Values{{
    {"scan", "[VLPM] a spinning head of 16 lasers", nullptr},
    {"channels", "[PCLV] 16 lasers from -15 to +15 deg, 2 deg apart", nullptr},
    {"azimuth.step",
     "[VLPM] 0.1-0.4 deg over 300-1200 RPM: 0.2 deg at 600 RPM (a 55.296 us firing cycle at 10 "
     "Hz turns 0.199 deg)",
     nullptr},
    {"rotation_rate", nullptr, "600 RPM, inside the manual's 300-1200 RPM [VLPM]"},
    {"beam_divergence", nullptr,
     "not published for the VLP-16: the sibling VLS-128's 3.0 mrad (horizontal) [VLS]"},
    {"beam_profile", nullptr, "the usual Gaussian: the manuals give no profile"},
    {"returns", "[VLPM] strongest, last or dual returns: dual, two a beam", nullptr},
}};
constexpr std::array<const char*, 3> kSpinning16Sources{{
    "[PCLV] PointCloudLibrary/pcl io/src/vlp_grabber.cpp (the VLP-16's elevations)",
    "[VLPM] Velodyne VLP-16 user manual, ch. 8; wiki.hanzheteng.com, Velodyne page",
    "[VLS] Velodyne VLS-128 manual, Table F-1",
}};

// --- spinning-64: a 64-channel spinning lidar, Ouster OS1-64 class ----------
void applySpinning64(LidarDefaults& d) {
  lidar::LidarSpec& s = d.lidar.spec;
  s.scan = lidar::ScanPattern::Spinning;
  evenChannels(d.lidar, 64, -16.6, 16.6);
  s.azimuth_step_deg = 360.0 / 1024.0;
  d.lidar.rotation_rate_Hz = 10.0;
  // 0.13 deg FWHM as a Gaussian's 1/e^2 full width: x 2 / sqrt(2 ln 2).
  s.divergence_rad = glm::radians(0.13) * 2.0 / std::sqrt(2.0 * std::log(2.0));
  s.profile = lidar::BeamProfile::Gaussian;
  s.returns.mode = lidar::ReturnMode::Strongest;
  s.returns.max = 1;
}
constexpr std::array<PresetValue, 7> kSpinning64Values{{
    {"scan", "[OS1] a spinning head", nullptr},
    {"channels",
     "[OS1] 64 beams over 33.2 deg vertical (spread evenly about the horizon here: the device's "
     "own spacing is per unit)",
     nullptr},
    {"azimuth.step", "[OS1] 1024 columns a turn (512 and 2048 too)", nullptr},
    {"rotation_rate", "[OS1] 10 or 20 Hz: 10", nullptr},
    {"beam_divergence",
     "[OS1] 0.13 deg FWHM, as the Gaussian's 1/e^2 full width (x 1.699, as HELIOS++ reads a "
     "datasheet's divergence [HEL])",
     nullptr},
    {"beam_profile", "[HEL] Gaussian beams", nullptr},
    {"returns", "[OS1] one return a beam, the strongest", nullptr},
}};
constexpr std::array<const char*, 2> kSpinning64Sources{{
    "[OS1] Ouster OS1 datasheet (850 nm revision)",
    "[HEL] 3dgeo-heidelberg/helios @fd94d1f python/pyhelios/data/scanners_tls.xml, "
    "src/maths/EnergyMaths.cpp",
}};

// --- multizone-8x8: VL53L5CX / VL53L8CH / TMF8828 class ---------------------
void applyMultizone(LidarDefaults& d) {
  lidar::LidarSpec& s = d.lidar.spec;
  s.scan = lidar::ScanPattern::Zones;
  s.grid.rows = 8;
  s.grid.columns = 8;
  s.grid.fov_horizontal_deg = 45.0;
  s.grid.fov_vertical_deg = 45.0;
  s.grid.zone_rays = 4;
  s.returns.mode = lidar::ReturnMode::All;
  s.returns.max = 4;
  d.time.bin_width_s = 250.4e-12;
  d.time.bins = 128;
}
constexpr std::array<PresetValue, 7> kMultizoneValues{{
    {"scan", "[DS13754] zones of one SPAD array under a flood VCSEL (940 nm [DS14161])", nullptr},
    {"grid", "[DS13754] 4x4 or 8x8 zones: 8x8 (the TMF8828 as four 4x4 captures [DS693])", nullptr},
    {"field_of_view", "[DS13754] 45 x 45 deg (63 deg diagonal); the VL53L8CX's the same [DS14161]",
     nullptr},
    {"zone_rays", nullptr,
     "4 x 4 receiver rays a zone (1.4 deg apart): a smooth surface's zone integral to ~1e-3; "
     "raise it for edges inside zones"},
    {"returns", "[ULD5] 1 to 4 targets a zone", nullptr},
    {"time.bin_width", "[CNH] a histogram bin is 37.5348 mm of range: 250.4 ps", nullptr},
    {"time.bins",
     "[TMFD] 128 bins a histogram (TMF882x); 128 x 37.5 mm = 4.8 m covers the 400 cm range "
     "[DS14161]",
     nullptr},
}};
constexpr std::array<const char*, 6> kMultizoneSources{{
    "[DS13754] ST VL53L5CX datasheet DS13754 Rev 2, Table 2 (as quoted in public code)",
    "[DS14161] st.com VL53L8CX datasheet; VL53L8CX ULD user manual",
    "[DS693] ams-OSRAM TMF8820/21/28 datasheet DS000693 v8",
    "[CNH] ST vl53lmz_plugin_cnh.h/.c (2023): the VL53L8CH's compact normalized histograms",
    "[TMFD] ams-OSRAM tmf882x.h; SparkFun TMF882X library docs",
    "[ULD5] ST VL53L5CX ULD, VL53L5CX_ResultsData",
}};

constexpr std::array<LidarPreset, 3> kPresets{{
    {"spinning-16",
     "a 16-channel spinning lidar in the class of the Velodyne VLP-16 (905 nm); the lasers' "
     "firing order within a cycle and the pulse's shape are not modelled",
     applySpinning16, kSpinning16Values, kSpinning16Sources},
    {"spinning-64",
     "a 64-channel spinning lidar in the class of the Ouster OS1-64 (850 nm); its channels' own "
     "spacing and staggered columns are not modelled",
     applySpinning64, kSpinning64Values, kSpinning64Sources},
    {"multizone-8x8",
     "a multizone direct-ToF sensor in the class of the ST VL53L5CX / VL53L8CH and ams TMF8828: "
     "8 x 8 zones of histograms under a flood emitter, each zone's distance computed on chip "
     "(zone_distance.npy); its pulse shape (about 10 bins [CNH]), ambient light and on-chip "
     "crosstalk removal are not modelled",
     applyMultizone, kMultizoneValues, kMultizoneSources},
}};

// A preset's value as the effective config writes it (one line).
std::string valueText(const LidarDefaults& d, const std::string& key) {
  if (key == "time.bin_width") {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g ps", d.time.bin_width_s * 1e12);
    return text;
  }
  if (key == "time.bins") return std::to_string(d.time.bins);
  YAML::Node node = lidarNode(d.lidar);
  std::stringstream path(key);
  std::string part;
  while (std::getline(path, part, '.')) node.reset(node[part]);
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

}  // namespace

std::span<const LidarPreset> lidarPresets() { return kPresets; }

const LidarPreset* findLidarPreset(std::string_view name) {
  return sensors::findPreset(lidarPresets(), name);
}

std::string describeLidarPreset(const LidarPreset& preset) {
  LidarDefaults d;
  preset.apply(d);
  std::string out = std::string(preset.name) + " (lidar): " + preset.device + "\n";
  for (const PresetValue& v : preset.values) {
    out += std::string("  ") + v.key + " = " + valueText(d, v.key);
    out += v.source ? std::string("  source: ") + v.source
                    : std::string("  assumed: ") + (v.note ? v.note : "");
    out += "\n";
  }
  out += "  sources:\n";
  for (const char* s : preset.sources) out += std::string("    ") + s + "\n";
  return out;
}

}  // namespace tofsim::config
