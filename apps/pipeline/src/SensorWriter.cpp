#include "tofsim/pipeline/SensorWriter.h"

#include "tofsim/imaging/LinePlot.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/PointCloudPly.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {
using sensors::SensorOutput;

// (H, W) or (H, W, C) as an Image; the sensor library promises these shapes.
Image asImage(const SensorOutput& o) {
  TOFSIM_CHECK_MSG(o.shape.size() == 2 || o.shape.size() == 3, o.name);
  const int32_t channels = o.shape.size() == 3 ? static_cast<int32_t>(o.shape[2]) : 1;
  Image image(static_cast<int32_t>(o.shape[1]), static_cast<int32_t>(o.shape[0]), channels);
  TOFSIM_CHECK_MSG(image.data.size() == o.data.size(), o.name);
  image.data = o.data;
  return image;
}

// EXR channel names readers recognise: Y for a grey image, RGB(A) for
// colour, numbered otherwise.
std::vector<std::string> channelNames(int32_t channels) {
  if (channels == 1) return {"Y"};
  if (channels == 3) return {"R", "G", "B"};
  if (channels == 4) return {"R", "G", "B", "A"};
  std::vector<std::string> names;
  for (int32_t c = 0; c < channels; ++c) names.push_back("C" + std::to_string(c));
  return names;
}

std::string withUnit(const std::string& text, const std::string& unit) {
  return unit.empty() ? text : text + " [" + unit + "]";
}

imaging::LinePlot asPlot(const SensorOutput& o) {
  TOFSIM_CHECK_MSG(o.shape.size() == 2, o.name);
  imaging::LinePlot plot;
  const auto bins = static_cast<std::size_t>(o.shape[1]);
  for (int64_t s = 0; s < o.shape[0]; ++s) {
    const auto first = o.data.begin() + static_cast<std::ptrdiff_t>(s * o.shape[1]);
    plot.series.emplace_back(first, first + static_cast<std::ptrdiff_t>(bins));
  }
  plot.labels = o.labels;
  plot.x0 = o.axis_start;
  plot.dx = o.axis_step;
  plot.xUnit = o.axis_unit;
  // The TDC's time: arrival at the camera, measured from the laser pulse.
  if (!o.axes.empty() && o.axes.back() == "t") plot.xLabel = "arrival time since the pulse";
  plot.yLabel = o.unit;
  plot.title = o.description;
  return plot;
}

// How the picture of `o` maps values to colours: its colormap, a diverging
// one for signed errors, the configured range, time ticks on a streak's rows.
imaging::ColorScale colorScale(const SensorOutput& o, const std::string& key, PlotRanges& ranges) {
  imaging::ColorScale scale;
  scale.colormap = o.colormap;
  scale.diverging = o.signed_values;
  scale.range = ranges.take(key);
  if (!o.axes.empty() && o.axes.front() == "t" && o.time) {
    scale.rows =
        imaging::RowAxis{o.time->start_s * 1e9, o.time->bin_width_s * 1e9, "arrival time [ns]"};
  }
  return scale;
}

// The Image `name` of `outputs` (an output's point-cloud companion), or none.
std::optional<Image> companion(const std::vector<SensorOutput>& outputs, const std::string& name) {
  const SensorOutput* o = sensors::findOutput(outputs, name, SensorOutput::Kind::Image);
  if (!o) return std::nullopt;
  return asImage(*o);
}

void writePointCloud(const std::filesystem::path& path, const SensorOutput& o, const Image& depth,
                     const std::vector<SensorOutput>& outputs, const capture::Camera& camera) {
  const std::optional<Image> intensity = companion(outputs, o.point_cloud->intensity);
  const std::optional<Image> confidence = companion(outputs, o.point_cloud->confidence);
  const std::optional<Image> mask = companion(outputs, o.point_cloud->mask);
  PointCloudImages images;
  images.mask = mask ? &*mask : nullptr;
  images.depth_m = &depth;
  images.intensity = intensity ? &*intensity : nullptr;
  images.confidence = confidence ? &*confidence : nullptr;
  images.comment = "tofsim " + o.name + ": " + o.description +
                   "; intensity: " + o.point_cloud->intensity +
                   ", confidence: " + o.point_cloud->confidence;
  writePointCloudPly(path, images, camera);
}

}  // namespace

std::vector<std::string> writeSensorOutputs(const std::filesystem::path& directory,
                                            const std::vector<SensorOutput>& outputs,
                                            const SensorRunInfo& run, PlotRanges& ranges) {
  std::filesystem::create_directories(directory);
  std::vector<std::string> files;
  std::map<std::string, PictureRange> pictureRanges;
  for (const SensorOutput& o : outputs) {
    TOFSIM_CHECK_MSG(o.streamed || static_cast<int64_t>(o.data.size()) == o.elementCount(), o.name);
    files.push_back(sensorFileName(o));
    const std::filesystem::path path = directory / files.back();
    switch (o.kind) {
      case SensorOutput::Kind::Array: {
        const io::NpyShape shape(o.shape.begin(), o.shape.end());
        // A streamed array is on disk already (SensorStreams.h); its shape,
        // axes and time still describe it in the metadata below.
        if (!o.streamed) io::writeNpy(path, shape, o.data.data());
        break;
      }
      case SensorOutput::Kind::Image: {
        const Image image = asImage(o);
        io::writeExr(path, image, channelNames(image.channels));
        // The same numbers as .npy, which NumPy reads without OpenEXR.
        files.push_back(sensorArrayFileName(o));
        io::writeNpy(directory / files.back(), io::NpyShape(o.shape.begin(), o.shape.end()),
                     o.data.data());
        if (o.point_cloud && run.camera) {
          files.push_back(o.name + ".ply");
          writePointCloud(directory / files.back(), o, image, outputs, *run.camera);
        }
        break;
      }
      case SensorOutput::Kind::ColorMappedImage: {
        imaging::ColorScale scale = colorScale(o, "sensors/" + run.spec->name + "/" + o.name, ranges);
        const bool bySensor = !scale.range && o.picture_range;
        if (bySensor) {
          scale.range = o.picture_range;
          scale.rangeSource = "the sensor's";
        }
        const imaging::ColorScaleUsed used =
            imaging::writeColormappedPng(path, asImage(o), withUnit(o.description, o.unit), scale);
        pictureRanges[o.name] = {used.lo,           used.hi,           used.automatic,
                                 used.loPercentile, used.hiPercentile, used.clippedLow,
                                 used.clippedHigh,  bySensor};
        break;
      }
      case SensorOutput::Kind::HistogramPlot:
        imaging::writeLinePlotPng(path, asPlot(o));
        break;
    }
  }
  for (const NamedMetadata& m : sensorMetadata(run, outputs, true, pictureRanges)) {
    files.push_back(m.name + ".json");
    writeFileAtomically(directory / files.back(), m.json);
  }
  return files;
}

}  // namespace tofsim::pipeline
