// Raster and zone scans through the pipeline (issue 43): a multizone
// sensor's zones equal the same scene rendered by tofsim's camera whose
// pixels are the zones (and whose pixels are the zones' receiver rays), lit
// by a co-located point light of the flood's intensity; a raster's beams
// land on a plane where their directions say; the device's own per-zone
// distance recovers a Gaussian echo's centre.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/TempDir.h"
#include "tofsim/capture/Camera.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/lidar/ZoneDistance.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

const std::string kStreet = std::string(TOFSIM_SOURCE_DIR) + "/configs/scenes/lidar_street.gltf";

constexpr int kZones = 8;      // zones a side
constexpr int kRays = 3;       // zone_rays: rays a side of a zone
constexpr double kFov = 40.0;  // degrees, both ways
constexpr int kBins = 600;     // of 200 ps: 0 .. 18 m of range
const char* kPosition = "[0, 1.5, 0]";
const char* kLookAt = "[10, 1, 3]";  // the car, the ground, a building's corner

class LidarZonesTest : public test::TempDirTest {
 protected:
  fs::path render(const std::string& name, const std::string& yaml) {
    const fs::path config = dir_ / (name + ".yaml");
    std::ofstream(config) << "scene: " << kStreet << "\n" << yaml;
    pipeline::RunOptions options;
    options.outputDirectory = dir_ / name;
    options.quiet = true;
    pipeline::runRender(config::loadRunConfig(config), options);
    return dir_ / name;
  }

  // The 8 x 8 zones (power 1 W); returns the waveforms (rows, columns, T)
  // and the field's solid angle from lidar.json.
  io::NpyArray zones(double& field_sr, const std::string& extra = "") {
    const fs::path out = render("zones" + std::to_string(extra.size()),
                                std::string("lidar:\n  scan: zones\n  position: ") + kPosition +
                                    "\n  orientation: {look_at: " + kLookAt +
                                    ", up: [0, 1, 0]}\n  grid: {rows: 8, columns: 8}\n"
                                    "  field_of_view: {horizontal: 40, vertical: 40}\n"
                                    "  zone_rays: 3\ntime: {bin_width: 200 ps, bins: 600}\n" +
                                    extra);
    const nlohmann::json meta = nlohmann::json::parse(std::ifstream(out / "lidar.json"));
    field_sr = meta["lidar"]["field_solid_angle_sr"].get<double>();
    return io::readNpy(out / "waveforms.npy");
  }

  // tofsim's camera at the same place, pixels x pixels over the same field
  // of view, direct light of a point light at the camera of intensity
  // `intensity`, each (sub-)sample's light in its own path's bin.
  io::NpyArray camera(int pixels, int samples, double intensity) {
    char yaml[1024];
    std::snprintf(yaml, sizeof yaml,
                  "camera: {position: %s, look_at: %s, up: [0, 1, 0], fov_y: %g, resolution: "
                  "[%d, %d]}\nlight: {attach_to_camera: true, intensity: %.17g}\n"
                  "time: {bin_width: 200 ps, bins: %d}\n"
                  "render: {backend: cpu, pixel_footprint: false, pixel_samples: %d, "
                  "indirect: {enabled: false}}\noutput: {steady: false, depth: false}\n",
                  kPosition, kLookAt, kFov, pixels, pixels, intensity, kBins, samples);
    const fs::path out = render("camera" + std::to_string(pixels), yaml);
    return io::readNpy(out / "transient.npy");
  }
};

// The camera's pixel (x, y) bin b, the mean of its R, G, B (a lidar sees
// one wavelength: the mean of the BRDF's channels).
double cameraValue(const io::NpyArray& t, int width, int x, int y, int b) {
  const std::size_t i = ((static_cast<std::size_t>(y) * width + x) * kBins + b) * 3;
  return (double(t.data[i]) + t.data[i + 1] + t.data[i + 2]) / 3.0;
}

capture::Camera cameraOf(int pixels) {
  capture::Camera c;
  c.position_world = {0.0f, 1.5f, 0.0f};
  c.look_at_world = {10.0f, 1.0f, 3.0f};
  c.up_world = {0.0f, 1.0f, 0.0f};
  c.fov_y_deg = static_cast<float>(kFov);
  c.width = c.height = pixels;
  return c;
}

// A camera whose pixels are the zones' receiver rays (24 x 24): zone (r, c)'s
// histogram is the sum over its rays of the ray's solid angle (the camera's
// own pixelSolidAngle_sr) times the radiance in its pixel, bin by bin. Both
// sides trace in float from directions made by other operations, so a hit's
// distance and cosine agree to ~1e-6 relative (CpuBackendTest's plane holds
// 1e-4 on radiance): each bin within 1e-4 of its value, plus 1e-6 of the
// zone's total for the sums' rounding.
TEST_F(LidarZonesTest, ZonesEqualACameraWhosePixelsAreTheZonesRays) {
  double field_sr = 0.0;
  const io::NpyArray w = zones(field_sr);
  ASSERT_EQ(w.shape, (std::vector<std::size_t>{8, 8, kBins}));
  const int pixels = kZones * kRays;
  const io::NpyArray t = camera(pixels, 1, 1.0 / field_sr);
  const capture::Camera cam = cameraOf(pixels);
  int lit = 0;
  double worst = 0.0;
  for (int r = 0; r < kZones; ++r) {
    for (int c = 0; c < kZones; ++c) {
      const float* zone = w.data.data() + (static_cast<std::size_t>(r) * kZones + c) * kBins;
      double total = 0.0;
      for (int b = 0; b < kBins; ++b) total += zone[b];
      lit += total > 0.0;
      for (int b = 0; b < kBins; ++b) {
        double expected = 0.0;
        for (int j = 0; j < kRays; ++j) {
          for (int i = 0; i < kRays; ++i) {
            const int x = c * kRays + i, y = pixels - 1 - (r * kRays + j);
            expected += cam.pixelSolidAngle_sr(x, y) * cameraValue(t, pixels, x, y, b);
          }
        }
        ASSERT_NEAR(zone[b], expected, 1e-4 * expected + 1e-6 * total)
            << "zone row " << r << " column " << c << " bin " << b;
        if (expected > 1e-3 * total) worst = std::max(worst, std::fabs(zone[b] / expected - 1.0));
      }
    }
  }
  EXPECT_GT(lit, 40);  // most zones see something within the 18 m axis
  RecordProperty("worst_relative", std::to_string(worst));
}

// The brief's camera: 8 x 8 pixels, the zones themselves, each averaging
// 3 x 3 samples where the zone's rays are. The zone weighs its rays by their
// solid angles omega_k, the pixel by 1/9 each, so bin by bin
// |zone - Omega_zone x pixel| <= max_k |9 omega_k / Omega_zone - 1| x
// Omega_zone x pixel (each bin a positive sum): that bound, from the
// geometry alone, plus the float allowance above.
TEST_F(LidarZonesTest, ZonesEqualACameraWhosePixelsAreTheZones) {
  double field_sr = 0.0;
  const io::NpyArray w = zones(field_sr);
  const io::NpyArray t = camera(kZones, kRays, 1.0 / field_sr);
  const capture::Camera fine = cameraOf(kZones * kRays);
  double worst = 0.0;
  for (int r = 0; r < kZones; ++r) {
    for (int c = 0; c < kZones; ++c) {
      double omega = 0.0, spread = 0.0;
      std::vector<double> rays;
      for (int j = 0; j < kRays; ++j) {
        for (int i = 0; i < kRays; ++i) {
          const int x = c * kRays + i, y = kZones * kRays - 1 - (r * kRays + j);
          rays.push_back(fine.pixelSolidAngle_sr(x, y));
          omega += rays.back();
        }
      }
      for (double o : rays) spread = std::max(spread, std::fabs(kRays * kRays * o / omega - 1.0));
      const float* zone = w.data.data() + (static_cast<std::size_t>(r) * kZones + c) * kBins;
      double total = 0.0;
      for (int b = 0; b < kBins; ++b) total += zone[b];
      for (int b = 0; b < kBins; ++b) {
        const double expected = omega * cameraValue(t, kZones, c, kZones - 1 - r, b);
        ASSERT_NEAR(zone[b], expected, (spread + 1e-4) * expected + 1e-6 * total)
            << "zone row " << r << " column " << c << " bin " << b;
        if (expected > 1e-3 * total) worst = std::max(worst, std::fabs(zone[b] / expected - 1.0));
      }
    }
  }
  RecordProperty("worst_relative", std::to_string(worst));
}

// One zone a task: the same bytes on one and three threads.
TEST_F(LidarZonesTest, ZonesAreTheSameBytesOnOneAndThreeThreads) {
  double field_sr = 0.0;
  const io::NpyArray one = zones(field_sr, "render: {threads: 1}\n");
  const io::NpyArray three = zones(field_sr, "render: {threads: 3}\n");
  ASSERT_EQ(one.data.size(), three.data.size());
  EXPECT_EQ(std::memcmp(one.data.data(), three.data.data(), one.data.size() * sizeof(float)), 0);
}

// A raster of 5 x 7 single-ray beams looking down at the ground (y = 0)
// from 2 m: each beam's direction is the pinhole's through its cell's
// centre (written here from the documented formula), and its return lies on
// the ground along it: range 2 / -d.y to half a bin (the echo's time is its
// bin's centre).
TEST_F(LidarZonesTest, RasterBeamsLandWhereTheirDirectionsSay) {
  const fs::path out = render(
      "raster",
      "lidar:\n  scan: raster\n  position: [0, 2, 0]\n  orientation: {look_at: [-2, 0, 2], up: "
      "[0, 1, 0]}\n  grid: {rows: 5, columns: 7}\n  field_of_view: {horizontal: 40, vertical: "
      "30}\n  beam_rays: 1\n  returns: {mode: first, max: 1}\ntime: {bin_width: 50 ps, bins: "
      "1000}\n");
  const io::NpyArray range = io::readNpy(out / "range.npy");
  const io::NpyArray dirs = io::readNpy(out / "beam_directions.npy");
  ASSERT_EQ(range.shape, (std::vector<std::size_t>{5, 7}));
  const glm::dvec3 forward = glm::normalize(glm::dvec3(-2, -2, 2));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tu = std::tan(glm::radians(20.0)), tv = std::tan(glm::radians(15.0));
  const double halfBin_m = 0.5 * 50e-12 * 299792458.0 / 2.0;
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 7; ++c) {
      const glm::dvec3 d = glm::normalize(forward + tu * (2.0 * (c + 0.5) / 7 - 1.0) * right +
                                          tv * (2.0 * (r + 0.5) / 5 - 1.0) * up);
      const std::size_t i = static_cast<std::size_t>(r) * 7 + c;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(dirs.data[i * 3 + k], d[k], 1e-6) << r << "," << c;
      EXPECT_NEAR(range.data[i], 2.0 / -d.y, halfBin_m + 1e-5) << r << "," << c;
    }
  }
}

// The device's own distance: a Gaussian echo sampled at the bin centres
// (sigma 1.5 bins, its centre anywhere in a bin) is found exactly by the
// log-parabola; one bin alone is its centre, two equal bins their edge.
TEST(ZoneDistanceTest, ThePeakFitFindsAGaussianEchosCentre) {
  TimeAxis axis;
  axis.bin_width_s = 250.4e-12;
  axis.bins = 128;
  for (const double centre : {40.5, 40.71, 41.0, 41.49, 63.2}) {
    std::vector<float> h(128, 0.0f);
    for (int b = 0; b < 128; ++b) {
      const double x = (b + 0.5 - centre) / 1.5;
      h[b] = static_cast<float>(std::exp(-0.5 * x * x));
    }
    const double expected = axis.depthOf_m(centre * axis.bin_width_s);
    EXPECT_NEAR(lidar::zoneDistance_m(h.data(), axis), expected, 1e-5) << centre;
  }
  std::vector<float> one(128, 0.0f);
  one[30] = 2.0f;
  EXPECT_NEAR(lidar::zoneDistance_m(one.data(), axis), axis.depthOf_m(axis.binCenter_s(30)), 1e-9);
  one[31] = 2.0f;  // two equal bins: their common edge
  EXPECT_NEAR(lidar::zoneDistance_m(one.data(), axis), axis.depthOf_m(axis.binStart_s(31)), 1e-9);
  EXPECT_EQ(lidar::zoneDistance_m(std::vector<float>(128, 0.0f).data(), axis), 0.0);
}

}  // namespace
}  // namespace tofsim
