#include "NlosSensors.h"

#include <cstdio>

#include "NlosTalFile.h"
#include "SensorReport.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/SensorWriter.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace {

// H + the first bounce as an image volume: pixel (row, col) is H's point
// row * sy + col, i.e. (sx, sy) or ((lx * ly + ...) * sx, sy), x index major.
TransientVolume sensorVolume(const NlosScanGeometry& scan, const NlosVolume& volume,
                             const std::vector<float>& firstBounce) {
  const auto bins = static_cast<std::size_t>(volume.axis.bins);
  const std::size_t points = volume.H.size() / bins;
  const int32_t columns = scan.sensorGrid[1];
  const auto rows = static_cast<int32_t>(points / columns);
  TransientVolume v(columns, rows, volume.axis, {"H"});
  float* out = v.data();
  for (std::size_t p = 0; p < points; ++p) {
    for (std::size_t t = 0; t < bins; ++t) {
      out[p * bins + t] = volume.H[t * points + p] + firstBounce[t * points + p];
    }
  }
  return v;
}

// spad_counts (rows, sy, bins) back into H's layout (bins, ...), on the TDC axis.
NlosVolume countsAsH(const sensors::SensorOutput& counts, const NlosVolume& rendered) {
  NlosVolume h = rendered;
  h.axis = *counts.time;
  const auto bins = static_cast<std::size_t>(h.axis.bins);
  const std::size_t points = counts.data.size() / bins;
  h.shape[0] = bins;
  h.H.assign(counts.data.size(), 0.0f);
  for (std::size_t p = 0; p < points; ++p) {
    for (std::size_t t = 0; t < bins; ++t) h.H[t * points + p] = counts.data[p * bins + t];
  }
  return h;
}

}  // namespace

std::vector<std::string> runNlosSensors(const config::RunConfig& config,
                                        const NlosScanGeometry& scan, const NlosVolume& volume,
                                        const std::vector<float>& firstBounce,
                                        const std::filesystem::path& directory,
                                        const Progress& progress) {
  std::vector<std::string> files;
  if (config.sensors.empty()) return files;
  const TransientVolume input = sensorVolume(scan, volume, firstBounce);
  PlotRanges ranges(config.output.plot_ranges);
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    throwIfInterrupted();
    const sensors::SensorSpec& spec = config.sensors[i];
    SensorRunInfo run{&spec, volume.axis, config.render.seed, {}};
    std::vector<sensors::SensorOutput> outputs;
    try {
      run.warnings = sensors::sensorWarnings(spec, sensors::shapeOf(input), nullptr);
      printSensorWarnings(spec, run.warnings);
      outputs = sensors::runSensor(spec, {&input, nullptr, nullptr, nullptr, config.render.seed});
    } catch (const InputError& e) {
      rethrowSensorError(config, i, e);
    }
    const std::filesystem::path relative = std::filesystem::path("sensors") / spec.name;
    for (const std::string& f : writeSensorOutputs(directory / relative, outputs, run, ranges)) {
      files.push_back((relative / f).string());
    }
    const sensors::SensorOutput* counts =
        sensors::findOutput(outputs, "spad_counts", sensors::SensorOutput::Kind::Array);
    if (counts && config.nlos->hdf5) {
      io::writeTalCapture(directory / relative / "capture.hdf5",
                          talCaptureOf(config, scan, countsAsH(*counts, volume)));
      files.push_back((relative / "capture.hdf5").string());
    }
    progress.message("sensor '" + spec.name + "': " + std::to_string(outputs.size()) + " outputs");
  }
  return files;
}

}  // namespace tofsim::pipeline
