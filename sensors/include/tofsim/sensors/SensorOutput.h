#pragma once
// What a sensor model produces: a list of named float arrays. Sensors do no file
// I/O and no drawing; the application layer writes each output according to its
// kind (see sensors/README.md, "Outputs").

#include <cstdint>
#include <string>
#include <vector>

namespace tofsim::sensors {

struct SensorOutput {
  enum class Kind {
    Array,             ///< numbers for programs: written as `<name>.npy`
    Image,             ///< float image (H, W) or (H, W, C): written as `<name>.exr`
    ColorMappedImage,  ///< (H, W) scalar for people: `<name>.png` through `colormap`, labelled
    HistogramPlot,     ///< (series, bins) curves: `<name>.png` line plot, x from axis_*
  };

  std::string name;  ///< file stem, e.g. "spad_counts", "streak_row042"
  Kind kind = Kind::Array;
  std::vector<int64_t> shape;  ///< C order
  std::vector<float> data;     ///< product(shape) values, or none when `streamed`
  /// Array only: the values went out through an ArrayWriter (SensorStream.h)
  /// as they were made, and `data` is empty.
  bool streamed = false;
  std::string unit;         ///< unit of the values, e.g. "m", "counts", "photo-electrons"
  std::string description;  ///< one line, usable as a plot title or colour bar label

  // ColorMappedImage and HistogramPlot only.
  std::string colormap;             ///< "viridis", "inferno", "turbo", ...
  std::vector<std::string> labels;  ///< HistogramPlot: one legend entry per series
  double axis_start = 0.0;          ///< HistogramPlot: x of the first bin's leading edge
  double axis_step = 1.0;           ///< HistogramPlot: x step per bin
  std::string axis_unit;            ///< HistogramPlot: unit of x, e.g. "ns"

  int64_t elementCount() const {
    int64_t n = 1;
    for (int64_t s : shape) n *= s;
    return n;
  }
};

/// The output with this name and kind, or nullptr.
const SensorOutput* findOutput(const std::vector<SensorOutput>& outputs, const std::string& name,
                               SensorOutput::Kind kind);

}  // namespace tofsim::sensors
