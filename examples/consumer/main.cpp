// A program of its own on an installed tofsim (find_package(tofsim)): loads a
// config, renders it on the CPU backend into memory, runs the config's sensors
// on the volume and prints what they made.
#include <cstdio>
#include <exception>
#include <numeric>

#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/sensors/RunSensor.h"

int main(int argc, char** argv) {
  using namespace tofsim;
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s CONFIG.yaml\n", argv[0]);
    return 2;
  }
  try {
    const config::RunConfig config = config::loadRunConfig(argv[1], {{"render.backend", "cpu"}});
    const scene::Scene scene = scene::loadGltf(config.scene_file);
    const capture::RenderJob job = pipeline::prepareCapture(config, scene);
    capture::VolumeCollector collector(job.camera().width, job.camera().height, job.settings.time,
                                       capture::kChannels);
    pipeline::Progress progress("render", /*quiet=*/true);
    const pipeline::RenderedCapture rendered =
        pipeline::renderCapture(config, job, gl::EglPlatform::Auto, {{&collector}, {}}, progress);
    const TransientVolume volume = collector.total();
    const std::vector<float>& v = volume.values();
    std::printf("tofsim %s, %s: %dx%d pixels x %d bins, total %.6g\n", pipeline::kVersion,
                rendered.device.c_str(), volume.width(), volume.height(), volume.bins(),
                std::accumulate(v.begin(), v.end(), 0.0));
    for (const sensors::SensorSpec& sensor : config.sensors) {
      sensors::SensorInputs inputs;
      inputs.volume = &volume;
      inputs.seed = config.render.seed;
      for (const sensors::SensorOutput& out : sensors::runSensor(sensor, inputs)) {
        if (out.kind != sensors::SensorOutput::Kind::Array) continue;  // pictures: the same numbers
        const double sum = std::accumulate(out.data.begin(), out.data.end(), 0.0);
        std::printf("%s/%s: %zu values, sum %.6g %s\n", sensor.name.c_str(), out.name.c_str(),
                    out.data.size(), sum, out.unit.c_str());
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
  return 0;
}
