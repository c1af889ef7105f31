#include "tofsim/pipeline/NlosEstimate.h"

#include <algorithm>
#include <limits>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

// Counted in double: a 4096^4-point exhaustive scan's bytes overflow 64 bits.
std::uintmax_t bytesOf(double bytes) {
  const auto most = std::numeric_limits<std::uintmax_t>::max();
  return bytes >= static_cast<double>(most) ? most : static_cast<std::uintmax_t>(bytes);
}

struct ScanSize {
  double bins = 0.0;
  double points = 1.0;      // H's points: sensor points, times laser points when exhaustive
  double perCapture = 1.0;  // points one capture gathers at once
  std::string keys;         // the keys that set H's size
  double hBytes() const { return 4.0 * bins * points; }
};

ScanSize scanSize(const config::RunConfig& config) {
  const config::NlosConfig& nlos = *config.nlos;
  ScanSize s;
  s.bins = static_cast<double>(config.render.time.bins);
  for (std::size_t n : nlosPointShape(nlos.scan, nlos.sensor_grid, nlos.laser_grid)) {
    s.points *= static_cast<double>(n);
  }
  const double sensorPoints = double(nlos.sensor_grid[0]) * double(nlos.sensor_grid[1]);
  s.perCapture = nlos.scan == config::NlosScan::Confocal ? 1.0 : sensorPoints;
  s.keys = nlos.scan == config::NlosScan::Exhaustive
               ? "time.bins x nlos.laser_grid x nlos.sensor_grid"
               : "time.bins x nlos.sensor_grid";
  return s;
}

// Each sensor's files for H's points, one row of sy points at a time (the
// sensors see H as rows of the sensor grid's y points).
double sensorBytes(const config::RunConfig& config, const sensors::SensorSpec& spec,
                   const ScanSize& size) {
  const int32_t columns = config.nlos->sensor_grid[1];
  const double rows = size.points / columns;
  return rows * static_cast<double>(
                    sensors::sensorOutputBytes(spec.params, columns, 1, config.render.time));
}

}  // namespace

OutputEstimate nlosOutputs(const config::RunConfig& config) {
  const ScanSize size = scanSize(config);
  const std::uintmax_t h = bytesOf(size.hBytes());
  OutputEstimate estimate;
  if (config.output.transient) {
    estimate.items.push_back({"H.npy", h, size.keys});
    estimate.items.push_back({"first_bounce.npy", h, size.keys});
  }
  if (config.nlos->hdf5) estimate.items.push_back({"capture.hdf5", h, size.keys + ", nlos.hdf5"});
  // H_steady/H_xt/H_yt.png (NlosPictures.h): 8-bit RGB as a bound for a
  // PNG, as a camera's pictures count (OutputProducts.cpp): the wall and two
  // projections of at most 2048 rows, widened to half their height.
  const auto& grid = config.nlos->sensor_grid;
  const double rows = std::min<double>(size.bins, 2048.0);
  const double pixels =
      grid[0] * grid[1] +
      (std::max<double>(grid[0], rows / 2) + std::max<double>(grid[1], rows / 2)) * rows;
  estimate.items.push_back({"H_*.png", bytesOf(3.0 * pixels), "nlos.sensor_grid, time.bins"});
  for (const sensors::SensorSpec& spec : config.sensors) {
    estimate.items.push_back({"sensors/" + spec.name, bytesOf(sensorBytes(config, spec, size)),
                              "nlos.sensor_grid x the sensor's bins"});
  }
  return estimate;
}

NlosMemory nlosHostMemory(const config::RunConfig& config) {
  const ScanSize size = scanSize(config);
  const double h = size.hBytes();
  const double collector = 2.0 * capture::kChannels * 4.0 * size.bins * size.perCapture;
  double sensorsCopy = 0.0;
  for (const sensors::SensorSpec& spec : config.sensors) {
    sensorsCopy = std::max(sensorsCopy, h + sensorBytes(config, spec, size));
  }
  const double copy = std::max(config.nlos->hdf5 ? h : 0.0, sensorsCopy);
  NlosMemory m;
  m.bytes = bytesOf(2.0 * h + std::max(collector, copy));
  m.detail = "H and first_bounce 2 x " + formatBytes(bytesOf(h)) + " (" + size.keys + "), ";
  if (collector >= copy) {
    m.detail += "one laser position's light " + formatBytes(bytesOf(collector)) +
                (config.nlos->scan == config::NlosScan::Confocal
                     ? " (time.bins)"
                     : " (time.bins x nlos.sensor_grid: every sensor point at once)");
  } else {
    m.detail += "a working copy of H " + formatBytes(bytesOf(copy)) +
                " (capture.hdf5 and the sensors' input: nlos.hdf5, sensors)";
  }
  return m;
}

void checkNlosMemory(const config::RunConfig& config) {
  const NlosMemory m = nlosHostMemory(config);
  const std::uintmax_t budget = config.render.memory_budget_bytes;
  if (m.bytes <= budget) return;
  const bool exhaustive = config.nlos->scan == config::NlosScan::Exhaustive;
  throw InputError(FileLoc{config.config_file.string()}, "render.memory_budget",
                   "the NLOS scan holds about " + formatBytes(m.bytes) + " in memory: " +
                       m.detail + "; that is over render.memory_budget (" + formatBytes(budget) +
                       "): lower nlos.sensor_grid" + (exhaustive ? ", nlos.laser_grid" : "") +
                       " or time.bins, or raise render.memory_budget");
}

}  // namespace tofsim::pipeline
