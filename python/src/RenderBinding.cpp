// _render: a config rendered into NumPy arrays. Without an output folder the
// volume is collected in memory (capture::VolumeCollector) through the CLI's
// way through a render (pipeline::renderCapture); with one, the CLI's own run
// (pipeline::runRender) writes the files and the arrays are read back from
// them. _Renderer keeps a scene and its renderer across in-memory renders
// (tofsim.Renderer). The GIL is released while rendering; Ctrl-C interrupts it.

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Arrays.h"
#include "Bindings.h"
#include "NlosBinding.h"
#include "SenseInputs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/FiniteSegments.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/RenderStats.h"
#include "tofsim/util/Interrupt.h"

namespace py = pybind11;

namespace tofsim::python {

namespace {

extern "C" void onSigint(int) { setPendingInterrupt(SIGINT); }

// Python's SIGINT handler only sets a flag that Python code polls, and no
// Python code runs while C++ renders. For the render's duration, a handler
// that records the signal where the renderers look for it (util/Interrupt.h);
// Python's handler comes back afterwards. Only on the main thread, which is
// where Python handles signals.
class SigintScope {
 public:
  explicit SigintScope(bool active) : active_(active) {
    if (!active_) return;
    setPendingInterrupt(0);
    struct sigaction action {};
    action.sa_handler = onSigint;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
  }
  ~SigintScope() {
    if (!active_) return;
    sigaction(SIGINT, &previous_, nullptr);
    setPendingInterrupt(0);
  }
  SigintScope(const SigintScope&) = delete;
  SigintScope& operator=(const SigintScope&) = delete;

 private:
  bool active_;
  struct sigaction previous_ {};
};

bool onMainThread() {
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("main_thread")().is(threading.attr("current_thread")());
}

// What a render hands back before it becomes Python objects (built without the GIL).
struct Rendered {
  std::optional<TransientVolume> transient, direct, indirect;
  /// bounce1 .. bounceN; `indirectIsBounce1`: N = 1, the indirect light is
  /// bounce 1 (the same array is handed back, not a copy).
  std::vector<TransientVolume> bounces;
  bool indirectIsBounce1 = false;
  Image steady;
  capture::RenderResult result;
  std::string device;
  std::vector<std::string> files;
};

// The CLI's way through a render (the capture loop, pipeline::CaptureLoop.h,
// with one capture through pipeline::CaptureChain: the same renderer,
// non-finite values written as 0 and counted, the time axis checked before
// and after under render.strict) into memory instead of files, through
// `prepared` (prepared for `config` already); `nameDevice`: say which device
// rendered (a one-off render does, a kept renderer's renders do not).
Rendered renderInMemory(const config::RunConfig& config, pipeline::PreparedRenderer& prepared,
                        bool nameDevice, bool quiet) {
  pipeline::Progress progress("render", quiet);
  std::optional<capture::VolumeCollector> collector;
  pipeline::CaptureConsumers consumers;
  std::optional<pipeline::RenderedCapture> rendered;
  int32_t bounces = 0;
  pipeline::CaptureLoopOptions loop;
  loop.withinCapture = [&](std::size_t done, std::size_t total, const std::string& what) {
    progress.update(done, total, what);
  };
  pipeline::renderCaptures(
      prepared, config, 1,
      [&](std::size_t) { return pipeline::prepareCapture(config, prepared.scene()); },
      [&](std::size_t, const capture::RenderJob& job) {
        // IR's light by bounce: with N > 1 bounces the segments carry bounce1 ..
        // bounceN (N more volumes in memory); with one, bounce 1 is the indirect light.
        const bool ir = config.renderer == config::RendererKind::InstantRadiosity;
        bounces = ir && job.settings.indirect.enabled ? job.settings.indirect.bounces : 0;
        collector.emplace(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                          job.settings.time, capture::kChannels, bounces > 1 ? bounces : 0);
        consumers = {{&*collector}, {}};
        for (int32_t k = 1; bounces > 1 && k <= bounces; ++k) consumers.bounces.push_back(k);
        return std::make_unique<pipeline::ConsumersSink>(config, job, consumers, rendered);
      },
      loop);
  if (nameDevice) {
    progress.message("device: " + rendered->device + " (backend " + rendered->backend + ")");
  }
  Rendered r;
  r.device = rendered->device;
  r.result = std::move(rendered->result);
  r.transient = collector->total();
  // As transient.npy: a float sum that overflowed is 0 (counted already).
  pipeline::zeroNonFinite(r.transient->data(), r.transient->values().size());
  r.steady = std::move(rendered->steady);
  r.direct = std::move(collector->direct);
  r.indirect = std::move(collector->indirect);
  r.bounces = std::move(collector->bounces);
  r.indirectIsBounce1 = bounces == 1;
  return r;
}

TransientVolume asVolume(io::NpyArray&& a, const TimeAxis& axis) {
  TransientVolume v(static_cast<int32_t>(a.shape.at(1)), static_cast<int32_t>(a.shape.at(0)), axis,
                    capture::defaultChannelNames(static_cast<int32_t>(a.shape.at(3))));
  v.values() = std::move(a.data);
  return v;
}

std::optional<TransientVolume> readVolume(const std::filesystem::path& file, const TimeAxis& axis) {
  if (!std::filesystem::exists(file)) return std::nullopt;
  return asVolume(io::readNpy(file), axis);
}

// The CLI's run, then the arrays it wrote. Volumes the config does not write
// (output.transient: false, no components) come back as None.
Rendered renderToFolder(const config::RunConfig& config, const std::string& directory, bool quiet) {
  pipeline::RunOptions options;
  options.outputDirectory = directory;
  options.quiet = quiet;
  pipeline::RunSummary summary = pipeline::runRender(config, options);
  Rendered r;
  r.result = std::move(summary.result);
  r.device = summary.device;
  r.files = summary.files;
  const TimeAxis& axis = config.render.time;
  const auto wrote = [&](std::string_view name) {
    return std::find(r.files.begin(), r.files.end(), name) != r.files.end();
  };
  const std::filesystem::path dir = summary.outputDirectory;
  namespace files = pipeline::files;
  // output.format: hdf5: the volumes are datasets of capture.h5 (named as
  // the .npy files without ".npy").
  std::optional<io::H5CaptureReader> h5;
  if (wrote(files::kCapture)) h5.emplace(dir / files::kCapture);
  const auto read = [&](const std::string& name) -> std::optional<TransientVolume> {
    const std::string dataset = name.substr(0, name.size() - 4);
    if (h5) {
      if (!h5->has(dataset)) return std::nullopt;
      return asVolume(h5->read(dataset), axis);
    }
    return wrote(name) ? readVolume(dir / name, axis) : std::nullopt;
  };
  r.transient = read(std::string(files::kTransient));
  r.direct = read(std::string(files::kDirect));
  r.indirect = read(std::string(files::kIndirect));
  for (int32_t k = 1; k <= capture::kMaxBounceComponents; ++k) {
    std::optional<TransientVolume> bounce = read(files::bounce(k));
    if (!bounce) break;
    r.bounces.push_back(std::move(*bounce));
  }
  if (r.transient) r.steady = steadyImage(*r.transient);
  return r;
}

py::object optionalVolume(std::optional<TransientVolume>& v) {
  return v ? py::object(volumeArray(std::move(*v))) : py::none();
}

// The config's sensors on the render in memory, as the CLI runs them on the
// segments (render.seed; the direct light, the bounces and the depth where a
// model takes them): name -> (arrays, metadata, warnings) (senseInputs).
py::dict senseRendered(const config::RunConfig& config, const Rendered& r) {
  py::dict results;
  if (config.sensors.empty() || !r.transient) return results;
  std::vector<const TransientVolume*> bounces;
  if (r.indirectIsBounce1 && r.indirect) bounces.push_back(&*r.indirect);
  for (const TransientVolume& b : r.bounces) bounces.push_back(&b);
  sensors::SensorInputs inputs;
  inputs.volume = &*r.transient;
  inputs.directOnly = r.direct ? &*r.direct : nullptr;
  inputs.groundTruthDepth_m = &r.result.depth_m;
  inputs.bounces = r.direct && !bounces.empty() ? &bounces : nullptr;
  inputs.seed = config.render.seed;
  for (const sensors::SensorSpec& spec : config.sensors) {
    results[py::str(spec.name)] = senseInputs(spec, inputs);
  }
  return results;
}

py::dict toPython(Rendered& r, const TimeAxis& axis) {
  py::dict d;
  d["transient"] = optionalVolume(r.transient);
  d["direct"] = optionalVolume(r.direct);
  d["indirect"] = optionalVolume(r.indirect);
  py::object bounces = py::none();
  if (r.indirectIsBounce1 && !d["indirect"].is_none()) {
    bounces = py::list();
    bounces.cast<py::list>().append(d["indirect"]);
  } else if (!r.bounces.empty()) {
    py::list list;
    for (TransientVolume& b : r.bounces) list.append(volumeArray(std::move(b)));
    bounces = list;
  }
  d["bounces"] = bounces;
  const Image& depth = r.result.depth_m;
  d["depth"] = ownedArray(std::move(r.result.depth_m.data), {depth.height, depth.width});
  d["steady"] = r.steady.data.empty()
                    ? py::object(py::none())
                    : py::object(ownedArray(std::move(r.steady.data),
                                            {r.steady.height, r.steady.width, r.steady.channels}));
  d["time"] = timeAxisDict(axis);
  // transient.json's stats (one writer), and the names they had here before.
  py::dict stats = py::module_::import("json").attr("loads")(pipeline::renderStatsText(r.result));
  stats["off_axis_before"] = r.result.offAxis.before;
  stats["off_axis_after"] = r.result.offAxis.after;
  d["stats"] = stats;
  d["device"] = r.device;
  d["files"] = r.files;
  return d;
}

py::dict render(const config::RunConfig& config, const std::optional<std::string>& outputDir,
                bool quiet) {
  const bool mainThread = onMainThread();
  if (config.nlos) {
    SigintScope sigint(mainThread);
    return renderNlos(config, outputDir, quiet);
  }
  if (config.lidar && !outputDir) {
    throw py::value_error(
        "a `lidar:` config renders into a folder for now: tofsim.render(config, output_dir=...)");
  }
  Rendered r;
  {
    py::gil_scoped_release released;
    SigintScope sigint(mainThread);
    if (outputDir) {
      r = renderToFolder(config, *outputDir, quiet);
    } else {
      pipeline::PreparedRenderer once(gl::eglPlatformFromEnvironment());
      once.prepare(config);
      r = renderInMemory(config, once, true, quiet);
    }
  }
  return toPython(r, config.render.time);
}

// A scene loaded and a renderer made once (pipeline::PreparedRenderer: its
// device; the scene's buffers and BVH at the first render), then any number
// of in-memory renders of configs of the same scene, renderer and backend:
// another camera, light, time axis, render settings. What would load the
// scene or make the renderer again is refused here (a new tofsim.Renderer
// says so in the user's code). Dataset generation, sweeps and optimisation
// loops pay the loading once (bench/README.md, "A renderer that stays loaded").
class KeptRenderer {
 public:
  KeptRenderer(const config::RunConfig& config, bool quiet)
      : quiet_(quiet), prepared_(gl::eglPlatformFromEnvironment()) {
    refuseNlosAndSequences(config);
    prepared_.prepare(config);
    // Its device now, not at the first render.
    device_ = prepared_.renderer(config).renderer->description();
  }

  py::dict render(const config::RunConfig& config) {
    refuseNlosAndSequences(config);
    if (const pipeline::SetupChange change = prepared_.changeFor(config); change.any()) {
      throw py::value_error(change.what +
                            " differs from the Renderer's; make a new tofsim.Renderer for it");
    }
    const bool mainThread = onMainThread();  // asks Python: before the GIL goes
    Rendered r;
    {
      py::gil_scoped_release released;
      SigintScope sigint(mainThread);
      r = renderInMemory(config, prepared_, false, quiet_);
    }
    py::dict sensors = senseRendered(config, r);
    py::dict d = toPython(r, config.render.time);
    d["sensors"] = sensors;
    return d;
  }

  /// How many times the renderer prepared the scene (IR; 0 for the reference).
  std::size_t scenePreparations() const { return prepared_.scenePreparations(); }

  std::string device() const { return device_; }

 private:
  static void refuseNlosAndSequences(const config::RunConfig& config) {
    if (config.nlos || config.sequence || config.lidar) {
      throw py::value_error(
          "tofsim.Renderer renders camera captures; render an `nlos:`, `lidar:` or `sequence:` config "
          "with tofsim.render");
    }
  }
  bool quiet_;
  pipeline::PreparedRenderer prepared_;
  std::string device_;
};

}  // namespace

// An OpenEXR image as (H, W, C) float32 (a sequence's frames' steady.exr).
py::array_t<float> readExrArray(const std::string& path) {
  Image image = io::readExr(path);
  return ownedArray(std::move(image.data), {image.height, image.width, image.channels});
}

// A dataset of a capture.h5 (output.format: hdf5), or None when it has none.
py::object readCaptureArray(const std::string& path, const std::string& dataset) {
  const io::H5CaptureReader reader(path);
  if (!reader.has(dataset)) return py::none();
  io::NpyArray a = reader.read(dataset);
  return ownedArray(std::move(a.data), std::vector<py::ssize_t>(a.shape.begin(), a.shape.end()));
}

void bindRender(py::module_& m) {
  m.def("_render", &render, py::arg("config"), py::arg("output_dir"), py::arg("quiet"));
  py::class_<KeptRenderer>(m, "_Renderer")
      .def(py::init<const config::RunConfig&, bool>(), py::arg("config"), py::arg("quiet"))
      .def("render", &KeptRenderer::render, py::arg("config"))
      .def("scene_preparations", &KeptRenderer::scenePreparations)
      .def("device", &KeptRenderer::device);
  m.def("_read_exr", &readExrArray, py::arg("path"));
  m.def("_read_capture", &readCaptureArray, py::arg("path"), py::arg("dataset"));
}

}  // namespace tofsim::python
