#pragma once
// What a sensor model produces: a list of named float arrays. Sensors do no file
// I/O and no drawing; the application layer writes each output according to its
// kind (see sensors/README.md, "Outputs").

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tofsim/volume/TimeAxis.h"

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

  // What the numbers mean, for the metadata written beside each file
  // (sensors/README.md, "Output metadata").
  /// One name per dimension of `shape`: "y" (image row, 0 = top), "x" (image
  /// column, 0 = left), "t" (a bin of `time`), "frequency" (index into the
  /// model's frequencies), "phase_step" (reference phase 2 pi k / N), "pixel"
  /// (index into `labels`), "order" (bounce order k: direct + bounces 1..k),
  /// "gate" (SPAD gate position k: the gate moved by k gate_step), "sweep"
  /// (CW-ToF wiggling sweep point j), "tap" (CW-ToF tap: 0 = A, 1 = B).
  std::vector<std::string> axes;
  /// The instrument's time axis, when one of `axes` is "t".
  std::optional<TimeAxis> time;
  /// Named numbers that say what the values are, in SI units with the unit in
  /// the name: {"frequency_Hz", 2e7}, {"range_m", 7.49}, {"row", 12}.
  std::vector<std::pair<std::string, double>> attributes;
  /// Signed values centred on 0 (errors): pictures use a diverging colour map.
  bool signed_values = false;
  /// Image only: the values are depths in m along each pixel's ray (NaN: no
  /// depth), and the writer also makes the point cloud `<name>.ply`, each
  /// point with the values of the Images named here (same shape) as its
  /// intensity and confidence (apps/pipeline, PointCloudPly.h); `mask`
  /// (empty: none) names an Image whose 0 pixels get no point (the SPAD's
  /// spad_returns: no return detected, though the estimator gives a depth).
  struct PointCloud {
    std::string intensity;
    std::string confidence;
    std::string mask;
  };
  std::optional<PointCloud> point_cloud;

  // ColorMappedImage and HistogramPlot only.
  std::string colormap;             ///< "viridis", "inferno", "turbo", ...
  /// ColorMappedImage: the colours' [lo, hi] where output.plot_ranges sets
  /// none; unset: a robust range of the data. For a picture whose values are
  /// counts with a drawn overlay (the phasor plot's semicircle), which the
  /// robust range would take for the data.
  std::optional<std::array<double, 2>> picture_range;
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
