#include "tofsim/pipeline/SensorStreams.h"

#include <algorithm>
#include <cstdio>
#include <variant>

#include "SensorReport.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/SensorWriter.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace {

using Clock = std::chrono::steady_clock;

// An Array output appended to its .npy (temporary until close()).
class NpyArrayWriter final : public sensors::ArrayWriter {
 public:
  NpyArrayWriter(const std::filesystem::path& path, const std::vector<int64_t>& shape)
      : writer_(path, io::NpyShape(shape.begin(), shape.end())) {}
  void append(const float* values, std::size_t count) override { writer_.append(values, count); }
  void close() override { writer_.commit(); }

 private:
  io::NpyStreamWriter writer_;
};

class NpyArrayStreams final : public sensors::ArrayStreams {
 public:
  explicit NpyArrayStreams(std::filesystem::path directory) : directory_(std::move(directory)) {}
  std::unique_ptr<sensors::ArrayWriter> open(const std::string& name,
                                             const std::vector<int64_t>& shape) override {
    std::filesystem::create_directories(directory_);
    return std::make_unique<NpyArrayWriter>(directory_ / (name + ".npy"), shape);
  }

 private:
  std::filesystem::path directory_;
};

}  // namespace

struct SensorStreams::Entry {
  std::size_t index = 0;           // in config.sensors
  std::filesystem::path relative;  // sensors/<name>
  NpyArrayStreams arrays;
  std::unique_ptr<sensors::SensorStream> stream;
  sensors::WindowLossMeter meter;
  Clock::duration busy{};             // time spent in the model, for the log
  std::vector<double> sampleTimes_s;  // SensorStream::sampleTimes_s
  bool inPass = true;                 // takes the current pass's spans
  bool reference = true;              // the current pass is the frame's time

  Entry(std::size_t i, std::filesystem::path rel, const std::filesystem::path& root,
        const sensors::SensorSpec& spec, const sensors::VolumeShape& shape)
      : index(i),
        relative(std::move(rel)),
        arrays(root / relative),
        meter(sensors::instrumentWindow(spec.params), shape) {}
};

std::optional<int32_t> sensorBounces(const config::RunConfig& config) {
  const bool asked = std::any_of(config.sensors.begin(), config.sensors.end(), [](const auto& s) {
    const auto* cwtof = std::get_if<sensors::CwTofParams>(&s.params);
    return cwtof && cwtof->multipath_by_order;
  });
  if (!asked) return std::nullopt;
  return surfaceVertices(config) - 1;  // the camera's surface point, then one per bounce
}

SensorStreams::SensorStreams(const config::RunConfig& config, const sensors::VolumeShape& shape,
                             bool withDirect, std::optional<int32_t> bounces,
                             const std::filesystem::path& outputDirectory,
                             const capture::Camera* camera, PsfPath psf)
    : config_(config), shape_(shape), outputDirectory_(outputDirectory), camera_(camera) {
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const sensors::SensorSpec& spec = config.sensors[i];
    auto entry = std::make_unique<Entry>(i, std::filesystem::path("sensors") / spec.name,
                                         outputDirectory, spec, shape);
    sensors::StreamOptions options;
    options.seed = config.render.seed;
    options.directOnly = withDirect;
    options.bounces = bounces;
    options.arrays = &entry->arrays;
    options.exposureSamples = config.sequence ? config.sequence->exposure_samples : 1;
    if (std::holds_alternative<sensors::CwTofParams>(spec.params)) {
      options.beforePsf = psf == PsfPath::Transient;  // for cwtof_psf_error
      if (psf == PsfPath::Raws) options.psfOnRaws = &config.camera.psf->kernel;
    }
    try {
      entry->stream = sensors::openSensor(spec, shape, options);
    } catch (const InputError& e) {
      rethrowSensorError(config, i, e);
    }
    entry->sampleTimes_s = entry->stream->sampleTimes_s();
    entries_.push_back(std::move(entry));
  }
}

std::vector<double> SensorStreams::passOffsets_s() const {
  std::vector<double> offsets;
  for (const std::unique_ptr<Entry>& e : entries_) {
    for (double t : e->sampleTimes_s) {
      if (t != 0.0) offsets.push_back(t);
    }
  }
  std::sort(offsets.begin(), offsets.end());
  offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
  offsets.insert(offsets.begin(), 0.0);
  return offsets;
}

void SensorStreams::beginPass(double offset_s) {
  for (const std::unique_ptr<Entry>& e : entries_) {
    sensors::SensorPass pass;
    pass.reference = offset_s == 0.0;
    for (std::size_t i = 0; i < e->sampleTimes_s.size(); ++i) {
      if (e->sampleTimes_s[i] == offset_s) pass.samples.push_back(i);
    }
    e->inPass = pass.reference || !pass.samples.empty();
    e->reference = pass.reference;
    if (e->inPass) e->stream->beginPass(pass);
  }
}

SensorStreams::~SensorStreams() = default;

void SensorStreams::consume(const sensors::PixelSpan& span) {
  for (const std::unique_ptr<Entry>& e : entries_) {
    if (!e->inPass) continue;
    const Clock::time_point start = Clock::now();
    e->stream->consume(span);
    if (e->reference) e->meter.consume(span);
    e->busy += Clock::now() - start;
  }
}

void SensorStreams::consumeBeforePsf(const sensors::PixelSpan& span) {
  for (const std::unique_ptr<Entry>& e : entries_) {
    const Clock::time_point start = Clock::now();
    e->stream->consumeBeforePsf(span);
    e->busy += Clock::now() - start;
  }
}

void SensorStreams::checkWindows() const {
  for (const std::unique_ptr<Entry>& e : entries_) {
    checkSensorWindow(config_, e->index, e->meter.fraction(), shape_.axis);
  }
}

std::vector<std::string> SensorStreams::finish(const Image* groundTruthDepth_m,
                                               const Progress& progress) {
  std::vector<std::string> files;
  PlotRanges ranges(config_.output.plot_ranges);
  for (const std::unique_ptr<Entry>& e : entries_) {
    throwIfInterrupted();
    const sensors::SensorSpec& spec = config_.sensors[e->index];
    const Clock::time_point start = Clock::now();
    std::vector<sensors::SensorOutput> outputs;
    SensorRunInfo run{&spec, shape_.axis, config_.render.seed, {}, camera_, {}};
    if (config_.sequence) run.sampleTimes_s = e->sampleTimes_s;
    try {
      run.warnings = sensors::sensorWarnings(spec, shape_, groundTruthDepth_m);
      printSensorWarnings(spec, run.warnings);
      outputs = e->stream->finish(groundTruthDepth_m);
    } catch (const InputError& error) {
      rethrowSensorError(config_, e->index, error);
    }
    for (const std::string& f :
         writeSensorOutputs(outputDirectory_ / e->relative, outputs, run, ranges)) {
      files.push_back((e->relative / f).string());
    }
    e->busy += Clock::now() - start;
    char line[160];
    std::snprintf(line, sizeof line, "sensor '%s' (%s): %zu outputs in %.2f s", spec.name.c_str(),
                  sensors::sensorTypeName(spec.params), outputs.size(),
                  std::chrono::duration<double>(e->busy).count());
    progress.message(line);
  }
  warnUntakenPlotRanges(ranges.untaken("sensors/"));
  return files;
}

}  // namespace tofsim::pipeline
