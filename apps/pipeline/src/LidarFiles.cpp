#include "LidarFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "SensorReport.h"
#include "TimeAxisJson.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/imaging/LinePlot.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/PointCloudFiles.h"
#include "tofsim/lidar/ScanGrid.h"
#include "tofsim/lidar/ZoneDistance.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/SensorMetadata.h"
#include "tofsim/pipeline/SensorWriter.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace {

nlohmann::ordered_json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// The picture with the highest ring on top (the arrays keep ring 0 in row
// 0), each ring drawn up to 8 rows tall so that a wide scan stays readable.
Image pictureRows(const Image& image) {
  const int32_t repeat = std::clamp(image.width / std::max(1, 8 * image.height), 1, 8);
  Image out(image.width, image.height * repeat, image.channels);
  for (int32_t y = 0; y < out.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      out.at(y, x, 0) = image.at(image.height - 1 - y / repeat, x, 0);
    }
  }
  return out;
}

// name.npy, name.exr (channel Y) and name.png of a (channels, azimuths) image.
void writeImage(const std::filesystem::path& dir, const std::string& name, const Image& image,
                const std::string& label, PlotRanges& ranges, std::vector<std::string>& files) {
  io::writeNpy(dir / (name + ".npy"), {std::size_t(image.height), std::size_t(image.width)},
               image.data.data());
  io::writeExr(dir / (name + ".exr"), image, {"Y"});
  imaging::ColorScale scale;
  scale.range = ranges.take(name);
  scale.nonPositiveIsNoData = true;
  scale.noDataLabel = "no return";
  imaging::writeColormappedPng(dir / (name + ".png"), pictureRows(image), label, scale);
  for (const char* ext : {".npy", ".exr", ".png"}) files.push_back(name + ext);
}

std::vector<float> beamDirections(const lidar::LidarSpec& s) {
  std::vector<float> out;
  out.reserve(static_cast<std::size_t>(s.channels()) * s.azimuths() * 3);
  for (int32_t r = 0; r < s.channels(); ++r) {
    for (int32_t a = 0; a < s.azimuths(); ++a) {
      const glm::vec3 d = lidar::beamDirection(s, r, a);
      out.insert(out.end(), {d.x, d.y, d.z});
    }
  }
  return out;
}

// A raster's or zones' layout (ScanGrid.h) into lidar.json's settings.
void gridJson(const lidar::LidarSpec& s, double frame_rate_Hz, nlohmann::ordered_json& j) {
  const lidar::GridFrame f = lidar::gridFrame(s);
  j["right"] = vec(glm::vec3(f.right));
  j["grid"] = {{"rows", s.grid.rows}, {"columns", s.grid.columns}};
  j["field_of_view_deg"] = {{"horizontal", s.grid.fov_horizontal_deg},
                            {"vertical", s.grid.fov_vertical_deg}};
  j["beam_direction_doc"] =
      "cell (row r, column c): normalize(forward + u right + up' v), u = tan(horizontal / 2) "
      "(2 (c + 1/2) / columns - 1), v = tan(vertical / 2) (2 (r + 1/2) / rows - 1), up' = right x "
      "forward: row 0 the lowest, column 0 the leftmost (a camera of columns x rows pixels over "
      "the field of view has them as its pixels, its row y = rows - 1 - r); "
      "beam_directions.npy holds them (rows, columns, 3)";
  if (s.scan == lidar::ScanPattern::Zones) {
    j["zone_rays"] = s.grid.zone_rays;
    j["zone_doc"] =
        "a flood emitter at the position fills the field of view (intensity power / "
        "field_solid_angle_sr); each zone integrates the radiance it returns over the zone's "
        "solid angle with zone_rays^2 rays through its sub-cells' centres, each weighted by its "
        "solid angle; zone_distance.npy: the device's own per-zone distance (the peak bin, "
        "refined by a parabola through the logs of its neighbours, or their energy-weighted "
        "centre where one is empty; 0: no light)";
    j["field_solid_angle_sr"] = lidar::fieldSolidAngle_sr(s);
  } else {
    j["beam_divergence_rad"] = s.divergence_rad;
    j["beam_profile"] = config::beamProfileName(s.profile);
    j["beam_rays"] = s.beam_rays;
    j["frame_rate_Hz"] = frame_rate_Hz;
    j["firing_doc"] =
        "cell (r, c) fires at ((rows - 1 - r) columns + c) / (rows columns frame_rate_Hz) after "
        "the frame's start (the points' time_offset): line by line from the top row, each left "
        "to right, evenly over the frame (an assumed MEMS raster timing, core/lidar RollingScan.h)";
  }
  j["power_W"] = s.power_W;
  j["returns"] = {{"mode", config::returnModeName(s.returns.mode)},
                  {"max", s.returns.max},
                  {"threshold", s.returns.threshold},
                  {"separation_m", s.returns.separation_m}};
}

nlohmann::ordered_json settingsJson(const config::LidarConfig& c) {
  const lidar::LidarSpec& s = c.spec;
  nlohmann::ordered_json j;
  if (!c.preset.empty()) j["preset"] = c.preset;
  j["scan"] = config::scanPatternName(s.scan);
  j["position"] = vec(s.position_world);
  j["forward"] = vec(s.forward_world);
  j["up"] = vec(s.up_world);
  if (s.gridScan()) {
    gridJson(s, c.frame_rate_Hz, j);
    return j;
  }
  j["elevations_deg"] = s.elevations_deg;
  j["azimuth_start_deg"] = s.azimuth_start_deg;
  j["azimuth_step_deg"] = s.azimuth_step_deg;
  j["azimuths"] = s.azimuths();
  j["beam_direction_doc"] =
      "beam (ring r, azimuth a): cos(el_r) (cos(az_a) forward + sin(az_a) (up x forward)) + "
      "sin(el_r) up, az_a = azimuth_start_deg + a azimuth_step_deg; beam_directions.npy holds "
      "them (channels, azimuths, 3)";
  j["beam_divergence_rad"] = s.divergence_rad;
  j["beam_profile"] = config::beamProfileName(s.profile);
  j["beam_rays"] = s.beam_rays;
  j["power_W"] = s.power_W;
  j["rotation_rate_Hz"] = c.rotation_rate_Hz;
  j["returns"] = {{"mode", config::returnModeName(s.returns.mode)},
                  {"max", s.returns.max},
                  {"threshold", s.returns.threshold},
                  {"separation_m", s.returns.separation_m}};
  if (c.multipath.enabled()) {  // written only when on: the direct runs' files stay
    const lidar::MultipathSettings& m = c.multipath;
    j["multipath"] = {
        {"bounces", m.bounces},
        {"spot_rays", m.spot_rays},
        {"receiver_rays", m.receiver_rays},
        {"receiver_fov_rad", m.receiver_fov_rad > 0.0 ? m.receiver_fov_rad : s.divergence_rad},
        {"vpls_per_bounce", m.vpls_per_bounce}};
  }
  return j;
}

std::string metadataJson(const config::RunConfig& config, const LidarFrame& frame,
                         const std::vector<std::string>& files) {
  const lidar::LidarSpec& s = config.lidar->spec;
  nlohmann::ordered_json j;
  j["format"] = "tofsim lidar capture";
  j["tofsim_version"] = kVersion;
  j["files"] = files;
  j["lidar"] = settingsJson(*config.lidar);
  j["waveforms_shape"] = {s.channels(), s.azimuths(), config.render.time.bins};
  j["axes"] = {"ring", "azimuth", "t"};
  j["value_unit"] = "W m^-2";
  j["value_doc"] =
      "waveforms.npy: the laser light reaching the receiver's aperture within the bin, as "
      "irradiance for an impulse of `power_W` at t = 0: each receiver ray brings power x share x "
      "f x cos / r^2 x T (f the surface's BRDF toward the lidar, the mean of R, G and B; T the "
      "medium's transmittance both ways); " +
      std::string(config.lidar->multipath.enabled()
                      ? "plus the multipath (lidar.multipath): each receiver point's radiance "
                        "from the spot's VPLs times its solid angle, in the bin of the whole path"
                      : "direct light only (lidar.multipath off)");
  j["echo_doc"] =
      "an echo is a run of bins above returns.threshold (runs closer than returns.separation "
      "merged): intensity = its summed bins, range = its energy-weighted mean time x (c / eta) / "
      "2; range.* and intensity.* hold the mode's first return (0: none), rows = rings (ring 0 "
      "first; the PNG draws the highest ring on top); points.ply / points.pcd every kept return";
  j["time"] = timeAxisJson(config.render.time);
  if (config.render.medium.present()) {
    const glm::vec3 t = config.render.medium.sigmaT();
    j["medium"] = {{"sigma_t_per_m", vec(t)},
                   {"doc", hasBeamBackscatter(config)
                               ? "attenuates every ray both ways; a scattering medium's single "
                                 "scattering along each beam's or zone's receiver rays (from "
                                 "backscatter.overlap on, BeamBackscatter.h) is in the waveforms"
                               : "attenuates every ray both ways; no backscatter in the "
                                 "waveforms (the medium does not scatter)"}};
  }
  const double beams = double(s.channels()) * s.azimuths();
  const double raysPerBeam =
      s.scan == lidar::ScanPattern::Zones
          ? double(s.grid.zone_rays) * s.grid.zone_rays
          : double(lidar::beamRays(s.beam_rays, s.divergence_rad, s.profile).size());
  j["stats"] = {{"seconds", frame.seconds},
                {"threads", frame.threads},
                {"beams", beams},
                {"rays", beams * raysPerBeam},
                {"beams_per_second", frame.seconds > 0.0 ? beams / frame.seconds : 0.0},
                {"beams_with_returns", frame.returns->beamsWithReturns},
                {"points", frame.returns->points.size()},
                {"lost_before_axis", frame.waveforms->lost.before},
                {"lost_after_axis", frame.waveforms->lost.after}};
  if (frame.fogReturns) {
    std::size_t fog = 0;
    for (uint8_t f : *frame.fogReturns) fog += f;
    j["stats"]["fog_returns"] = fog;
    j["fog_returns_doc"] =
        "returns whose bins hold no receiver ray's surface: the medium's false returns "
        "(fog_points.ply holds them alone; points.ply holds every return)";
  }
  return j.dump(2) + "\n";
}

// waveforms.png: the lidar.plot_beams' waveforms against range, over the
// bins that hold their light (and 1 m either side), in uW m^-2.
void writeWaveformPlot(const config::RunConfig& config, const lidar::LidarWaveforms& waveforms,
                       const std::filesystem::path& dir, std::vector<std::string>& files) {
  const config::LidarConfig& lidar = *config.lidar;
  if (lidar.plot_beams.empty()) return;
  const TimeAxis& axis = waveforms.axis;
  const int32_t bins = axis.bins;
  std::vector<std::vector<float>> beams;
  for (const auto& [ring, a] : lidar.plot_beams) {
    beams.emplace_back(static_cast<std::size_t>(bins));
    waveforms.beamWaveform(static_cast<std::size_t>(ring) * lidar.spec.azimuths() + a,
                           beams.back().data());
  }
  const double toRange = axis.camera_unwarp ? axis.index_of_refraction
                                            : 2.0 * axis.index_of_refraction;
  const double binRange_m = axis.bin_width_m() / toRange;
  int32_t first = bins, last = -1;
  for (const std::vector<float>& w : beams) {
    for (int32_t b = 0; b < bins; ++b) {
      if (w[b] > 0.0f) {
        first = std::min(first, b);
        last = std::max(last, b);
      }
    }
  }
  const auto pad = static_cast<int32_t>(std::ceil(1.0 / binRange_m));
  first = last < 0 ? 0 : std::max(0, first - pad);
  last = last < 0 ? bins - 1 : std::min(bins - 1, last + pad);
  imaging::LinePlot plot;
  for (std::size_t i = 0; i < beams.size(); ++i) {
    const auto& [ring, a] = lidar.plot_beams[i];
    const std::vector<float>& w = beams[i];
    std::vector<float> series;
    for (int32_t b = first; b <= last; ++b) series.push_back(w[b] * 1e6f);
    plot.series.push_back(std::move(series));
    char label[96];
    if (lidar.spec.gridScan()) {
      std::snprintf(label, sizeof label, "row %d, column %d", ring, a);
    } else {
      std::snprintf(label, sizeof label, "ring %d (%.1f deg), azimuth %.1f deg", ring,
                    lidar.spec.elevations_deg[static_cast<std::size_t>(ring)],
                    lidar.spec.azimuthOf_deg(a));
    }
    plot.labels.push_back(label);
  }
  plot.x0 = axis.start_m() / toRange + first * binRange_m;
  plot.dx = binRange_m;
  plot.xUnit = "m";
  plot.xLabel = "range";
  plot.yLabel = "irradiance per bin [uW m^-2]";
  const bool backscatter = hasBeamBackscatter(config);
  plot.title = std::string("lidar waveforms (direct light") +
               (config.lidar->multipath.enabled() ? ", multipath" : "") +
               (backscatter ? ", the medium's backscatter" : "") + ")";
  imaging::writeLinePlotPng(dir / "waveforms.png", plot);
  files.push_back("waveforms.png");
}

// A multizone sensor's own distance per zone (ZoneDistance.h).
Image zoneDistances(const TransientVolume& volume) {
  Image out(volume.width(), volume.height(), 1);
  for (int32_t y = 0; y < volume.height(); ++y) {
    for (int32_t x = 0; x < volume.width(); ++x) {
      out.at(y, x, 0) = static_cast<float>(
          lidar::zoneDistance_m(volume.data() + volume.index(y, x, 0, 0), volume.axis()));
    }
  }
  return out;
}

// The configured sensors on the waveforms: pixels are beams.
void writeSensors(const config::RunConfig& config, const TransientVolume& volume,
                  const std::filesystem::path& dir, PlotRanges& ranges, const Progress& progress,
                  std::vector<std::string>& files) {
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    throwIfInterrupted();
    const sensors::SensorSpec& spec = config.sensors[i];
    SensorRunInfo run{&spec, volume.axis(), config.render.seed, {}};
    std::vector<sensors::SensorOutput> outputs;
    try {
      run.warnings = sensors::sensorWarnings(spec, sensors::shapeOf(volume), nullptr);
      printSensorWarnings(spec, run.warnings);
      outputs = sensors::runSensor(spec, {&volume, nullptr, nullptr, nullptr, config.render.seed});
    } catch (const InputError& e) {
      rethrowSensorError(config, i, e);
    }
    const std::filesystem::path relative = std::filesystem::path("sensors") / spec.name;
    for (const std::string& f : writeSensorOutputs(dir / relative, outputs, run, ranges)) {
      files.push_back((relative / f).string());
    }
    progress.message("sensor '" + spec.name + "': " + std::to_string(outputs.size()) + " outputs");
  }
}

// waveforms.npy (channels, azimuths, T): the volume where kept, else the
// beams' nonzero bins expanded a block of beams at a time (no frame-sized
// buffer: 64 x 1024 beams of 1000 bins are 262 MB).
void writeWaveformsNpy(const lidar::LidarSpec& s, const lidar::LidarWaveforms& waveforms,
                       const std::filesystem::path& path) {
  const io::NpyShape shape{std::size_t(s.channels()), std::size_t(s.azimuths()),
                           std::size_t(waveforms.axis.bins)};
  if (waveforms.volume.size() > 0) {
    io::writeNpy(path, shape, waveforms.volume.data());
    return;
  }
  io::NpyStreamWriter out(path, shape);
  const std::size_t bins = shape[2];
  const std::size_t beams = waveforms.sparse.beams();
  constexpr std::size_t kBlock = 256;
  std::vector<float> block(kBlock * bins);
  for (std::size_t begin = 0; begin < beams; begin += kBlock) {
    const std::size_t n = std::min(kBlock, beams - begin);
    for (std::size_t b = 0; b < n; ++b) waveforms.beamWaveform(begin + b, block.data() + b * bins);
    out.append(block.data(), n * bins);
  }
  out.commit();
}

}  // namespace

bool hasBeamBackscatter(const config::RunConfig& config) {
  return config.render.medium.scatters();
}

std::vector<std::string> writeLidarFiles(const config::RunConfig& config, const LidarFrame& frame,
                                         const std::filesystem::path& dir,
                                         const Progress& progress) {
  const lidar::LidarSpec& s = config.lidar->spec;
  const TransientVolume& volume = frame.waveforms->volume;
  std::vector<std::string> files;
  if (config.output.transient) {
    writeWaveformsNpy(s, *frame.waveforms, dir / "waveforms.npy");
    files.push_back("waveforms.npy");
  }
  PlotRanges ranges(config.output.plot_ranges);
  writeImage(dir, "range", frame.returns->range_m, "range [m]", ranges, files);
  writeImage(dir, "intensity", frame.returns->intensity, "intensity [W m^-2]", ranges, files);
  if (s.scan == lidar::ScanPattern::Zones) {
    writeImage(dir, "zone_distance", zoneDistances(volume), "zone distance [m]", ranges, files);
  }
  io::writeNpy(dir / "beam_directions.npy",
               {std::size_t(s.channels()), std::size_t(s.azimuths()), 3}, beamDirections(s).data());
  files.push_back("beam_directions.npy");
  lidar::writePly(dir / "points.ply", frame.returns->points, "tofsim lidar returns");
  lidar::writePcd(dir / "points.pcd", frame.returns->points);
  files.insert(files.end(), {"points.ply", "points.pcd"});
  if (frame.fogReturns) {  // the medium's false returns alone
    std::vector<lidar::LidarPoint> fog;
    for (std::size_t i = 0; i < frame.fogReturns->size(); ++i) {
      if ((*frame.fogReturns)[i]) fog.push_back(frame.returns->points[i]);
    }
    lidar::writePly(dir / "fog_points.ply", fog, "tofsim lidar: the medium's false returns");
    files.push_back("fog_points.ply");
  }
  writeWaveformPlot(config, *frame.waveforms, dir, files);
  if (!config.sensors.empty()) writeSensors(config, volume, dir, ranges, progress, files);
  warnUntakenPlotRanges(ranges.untaken(""));
  std::vector<std::string> listed = files;
  listed.push_back("config.effective.yaml");
  writeFileAtomically(dir / "lidar.json", metadataJson(config, frame, listed));
  files.push_back("lidar.json");
  return files;  // the effective config follows (RunFolder::finish)
}

}  // namespace tofsim::pipeline
