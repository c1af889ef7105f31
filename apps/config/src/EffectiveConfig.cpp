// Writes a RunConfig back as YAML with every default filled in, so that the
// outputs of a run say exactly what produced them and can be re-run as is.

#include <yaml-cpp/yaml.h>

#include "CameraFields.h"
#include "FieldEmit.h"
#include "LensConfig.h"
#include "LidarSection.h"
#include "LightFields.h"
#include "MaterialSection.h"
#include "MediumSection.h"
#include "NlosFields.h"
#include "OutputFields.h"
#include "RaysFields.h"
#include "RunFields.h"
#include "SequenceFields.h"
#include "ShortestNumber.h"
#include "TimeFields.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {

namespace {

YAML::Node vec(const glm::vec3& v) {
  YAML::Node n(YAML::NodeType::Sequence);
  for (int i = 0; i < 3; ++i) n.push_back(shortest(v[i]));
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

YAML::Node flowPair(double a, double b) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.push_back(shortest(a));
  n.push_back(shortest(b));
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

YAML::Node lensNode(const CameraConfig& c) {
  const capture::Lens& lens = *c.camera.lens;
  YAML::Node l;
  if (!c.lens_calibration.empty()) {
    l["calibration"] = c.lens_calibration;
    return l;
  }
  YAML::Node m(YAML::NodeType::Sequence);
  for (const double v : {lens.fx, 0.0, lens.cx, 0.0, lens.fy, lens.cy, 0.0, 0.0, 1.0}) {
    m.push_back(shortest(v));
  }
  m.SetStyle(YAML::EmitterStyle::Flow);
  l["camera_matrix"] = m;
  YAML::Node d(YAML::NodeType::Sequence);
  for (std::size_t i = 0; i < distortionCount(lens); ++i) d.push_back(shortest(lens.distortion[i]));
  d.SetStyle(YAML::EmitterStyle::Flow);
  l["distortion"] = d;
  return l;
}

YAML::Node psfNode(const PsfConfig& psf) {
  YAML::Node p;
  if (!psf.file.empty()) {
    p["file"] = psf.file;
  } else {
    emitFields(p, kPsfFields, psf);
  }
  return p;
}

const char* vignettingText(const capture::Vignetting& v) {
  switch (v.kind) {
    case capture::Vignetting::Kind::Cos4:
      return "cos4";
    case capture::Vignetting::Kind::Map:
      return v.file.c_str();
    case capture::Vignetting::Kind::None:
      break;
  }
  return "none";
}

YAML::Node cameraNode(const CameraConfig& c) {
  YAML::Node n;
  emitFields(n, kCameraFields, c, [&](const std::string& key) {
    if (key == "lens" && c.camera.lens) {
      n[key] = lensNode(c);
    } else if (key == "resolution") {
      YAML::Node res(YAML::NodeType::Sequence);
      res.push_back(c.camera.width);
      res.push_back(c.camera.height);
      res.SetStyle(YAML::EmitterStyle::Flow);
      n[key] = res;
    } else if (key == "vignetting") {
      n[key] = vignettingText(c.vignetting);
    } else if (key == "psf" && c.psf) {
      n[key] = psfNode(*c.psf);
    }
  });
  // A lens's camera matrix sets the field of view; the aperture's keys only
  // with an aperture, so that a pinhole's effective config keeps its bytes.
  if (c.camera.lens) n.remove("fov_y");
  if (!c.camera.defocused()) {
    for (const char* key : {"aperture", "focus_distance", "aperture_samples"}) n.remove(key);
  }
  return n;
}

YAML::Node raysNode(const RaysConfig& r) {
  YAML::Node n;
  emitFields(n, kRaysFields, r, [&](const std::string& key) {
    if (key == "file") n[key] = r.file;
    if (key == "resolution") n[key] = flowPair(r.imager.width, r.imager.height);
  });
  return n;
}

YAML::Node nlosNode(const NlosConfig& c) {
  YAML::Node n;
  emitFields(n, kNlosFields, c, [&](const std::string& key) {
    if (key == "sensor_grid") {
      n[key] = flowPair(c.sensor_grid[0], c.sensor_grid[1]);
    } else if (key == "laser_grid" && c.scan == NlosScan::Exhaustive) {
      n[key] = flowPair(c.laser_grid[0], c.laser_grid[1]);
    } else if (key == "laser_point" && c.scan == NlosScan::Single) {
      n[key] = flowPair(c.laser_point.x, c.laser_point.y);
    } else if (key == "laser_aperture" && c.scan == NlosScan::Exhaustive) {
      YAML::Node a(YAML::NodeType::Sequence);
      a.push_back(flowPair(c.laser_aperture_start.x, c.laser_aperture_start.y));
      a.push_back(flowPair(c.laser_aperture_end.x, c.laser_aperture_end.y));
      a.SetStyle(YAML::EmitterStyle::Flow);
      n[key] = a;
    } else if (key == "sensor_origin") {
      n[key] = vec(c.sensor_origin);
    } else if (key == "laser_origin") {
      n[key] = vec(c.laser_origin);
    } else if (key == "laser_power") {
      n[key] = vec(c.laser_power_W);
    }
  });
  return n;
}

YAML::Node sequenceNode(const SequenceConfig& c) {
  YAML::Node n;
  if (c.rate_Hz > 0.0) {  // start, rate and count: the times follow
    emitFields(n, kSequenceFields, c, [](const std::string&) {});
    return n;
  }
  YAML::Node times(YAML::NodeType::Sequence);
  for (double t : c.times_s) times.push_back(durationText(t));
  times.SetStyle(YAML::EmitterStyle::Flow);
  n["times"] = times;
  n["exposure_samples"] = c.exposure_samples;
  n["video"] = c.video;
  return n;
}

YAML::Node lightNode(const LightConfig& c) {
  YAML::Node n;
  emitFields(n, kLightFields, c);
  return n;
}

YAML::Node renderNode(const RunConfig& config) {
  YAML::Node n;
  emitFields(n, kRenderFields, config, [&](const std::string& key) {
    YAML::Node section;
    if (key == "indirect") {
      emitFields(section, kIndirectFields, config.render.indirect);
      // Only with a medium: a config without one keeps its effective bytes
      // (and its run content key).
      if (!config.medium) {
        section.remove("medium_vpls");
        section.remove("medium_camera_rays");
      }
    }
    if (key == "reference") emitFields(section, kReferenceFields, config.reference);
    n[key] = section;
  });
  return n;
}

YAML::Node outputNode(const OutputConfig& o) {
  YAML::Node n;
  emitFields(n, kOutputFields, o, [&](const std::string& key) {
    if (key == "components") {
      YAML::Node components(YAML::NodeType::Sequence);
      if (o.direct) components.push_back("direct");
      if (o.indirect) components.push_back("indirect");
      for (const int32_t k : o.bounces) components.push_back("bounce" + std::to_string(k));
      components.SetStyle(YAML::EmitterStyle::Flow);
      n[key] = components;
    } else if (key == "plot_ranges") {
      YAML::Node ranges(YAML::NodeType::Map);
      for (const auto& [name, range] : o.plot_ranges) ranges[name] = flowPair(range[0], range[1]);
      n[key] = ranges;
    }
  });
  return n;
}

}  // namespace

std::string effectiveConfigYaml(const RunConfig& config) {
  YAML::Node root;
  root["scene"] = std::filesystem::absolute(config.scene_file).lexically_normal().string();
  if (config.nlos) {
    root["nlos"] = nlosNode(*config.nlos);
  } else if (config.lidar) {
    root["lidar"] = lidarNode(*config.lidar);
  } else {
    if (config.rays) {
      root["rays"] = raysNode(*config.rays);
    } else {
      root["camera"] = cameraNode(config.camera);
    }
    root["light"] = lightNode(config.light);
  }
  if (config.sequence) root["sequence"] = sequenceNode(*config.sequence);
  if (config.sequence && config.lidar) {  // a camera's keys, refused beside a lidar
    root["sequence"].remove("video");
    root["sequence"].remove("exposure_samples");
  }
  YAML::Node time;
  emitFields(time, kTimeFields, config.render.time);
  root["time"] = time;
  // Only when given: a config without a medium keeps its effective bytes
  // (and its run content key).
  if (config.medium) root["medium"] = mediumNode(config);
  if (!config.render.media.empty()) root["media"] = mediaNode(config);
  root["render"] = renderNode(config);
  YAML::Node output = outputNode(config.output);
  if (config.nlos || config.lidar) {  // the keys they read (checkNlosRun, checkLidarRun)
    YAML::Node kept;
    for (const char* key : {"directory", "transient", "max_bytes"}) kept[key] = output[key];
    if (config.lidar) kept["plot_ranges"] = output["plot_ranges"];
    output = kept;
  }
  root["output"] = output;
  // Only when set: a config without materials keeps its effective bytes.
  if (!config.materials.empty()) root["materials"] = materialsNode(config.materials);
  root["sensors"] = sensorsToYaml(config.sensors);
  YAML::Emitter out;
  out << root;
  return std::string("# Effective tofsim config: every key with its value, defaults included.\n") +
         out.c_str() + "\n";
}

}  // namespace tofsim::config
