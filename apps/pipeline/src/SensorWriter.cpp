#include "tofsim/pipeline/SensorWriter.h"

#include "tofsim/imaging/LinePlot.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
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
  plot.yLabel = o.unit;
  plot.title = o.description;
  return plot;
}

}  // namespace

std::vector<std::string> writeSensorOutputs(const std::filesystem::path& directory,
                                            const std::vector<SensorOutput>& outputs) {
  std::filesystem::create_directories(directory);
  std::vector<std::string> files;
  for (const SensorOutput& o : outputs) {
    TOFSIM_CHECK_MSG(o.streamed || static_cast<int64_t>(o.data.size()) == o.elementCount(), o.name);
    switch (o.kind) {
      case SensorOutput::Kind::Array: {
        const io::NpyShape shape(o.shape.begin(), o.shape.end());
        files.push_back(o.name + ".npy");
        // A streamed array is on disk already (SensorStreams.h).
        if (!o.streamed) io::writeNpy(directory / files.back(), shape, o.data.data());
        break;
      }
      case SensorOutput::Kind::Image: {
        const Image image = asImage(o);
        files.push_back(o.name + ".exr");
        io::writeExr(directory / files.back(), image, channelNames(image.channels));
        break;
      }
      case SensorOutput::Kind::ColorMappedImage:
        files.push_back(o.name + ".png");
        imaging::writeColormappedPng(directory / files.back(), asImage(o),
                                     withUnit(o.description, o.unit), o.colormap);
        break;
      case SensorOutput::Kind::HistogramPlot:
        files.push_back(o.name + ".png");
        imaging::writeLinePlotPng(directory / files.back(), asPlot(o));
        break;
    }
  }
  return files;
}

}  // namespace tofsim::pipeline
