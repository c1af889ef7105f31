#pragma once
// The JSON that says how to read a sensor's outputs without guessing
// (sensors/README.md, "Output metadata"): per output name, the array's shape,
// dtype and axis names, the unit of its values, the instrument's time axis
// (start, bin width, bins; in seconds and metres), what the model was given
// (parameters in SI units, seed, the render's axis) and the warnings of the
// run. Written as sensors/<sensor>/<output>.json by the CLI and returned with
// each array by the Python module's tofsim.sense, the same text for both but
// for what only files have: the file names and the colour range each picture
// was drawn with.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::capture {
struct Camera;
}

namespace tofsim::pipeline {

/// What one sensor run was: the spec, the volume's time axis, the seed and
/// what sensorWarnings said; with the pinhole camera whose pixels the sensor
/// saw, depth Images also go out as point clouds (PointCloudPly.h).
struct SensorRunInfo {
  const sensors::SensorSpec* spec = nullptr;
  TimeAxis render;
  uint64_t seed = 0;
  std::vector<std::string> warnings;
  const capture::Camera* camera = nullptr;  ///< nullptr: no point clouds
  /// A frame of a capture sequence: when the sensor sampled the light
  /// (SensorStream::sampleTimes_s); empty: a static capture.
  std::vector<double> sampleTimes_s;
};

/// One document per output name, in output order: an Image and the
/// ColorMappedImage drawn from it share one. With `files`, each lists the
/// files written for that name (sensorFileName); the Python module, which
/// writes none, passes false.
struct NamedMetadata {
  std::string name;
  std::string json;  ///< pretty-printed, ends in a newline
};
/// The colour range a picture was drawn with (imaging::ColorScaleUsed), in
/// the unit of its values: the JSON's "picture.range".
struct PictureRange {
  double lo = 0.0, hi = 1.0;
  bool automatic = true;  ///< from the data (percentiles below), else output.plot_ranges
  double loPercentile = 0.0, hiPercentile = 100.0;  ///< of lo and hi among the valid pixels
  bool clippedLow = false, clippedHigh = false;     ///< values lie below lo / above hi
  bool bySensor = false;  ///< not automatic: the sensor's SensorOutput::picture_range
};

/// `ranges`: the colour ranges of the pictures drawn, by output name (none
/// for the Python module, which draws none).
std::vector<NamedMetadata> sensorMetadata(const SensorRunInfo& run,
                                          const std::vector<sensors::SensorOutput>& outputs,
                                          bool files,
                                          const std::map<std::string, PictureRange>& ranges = {});

/// The file an output is written to: <name>.npy (Array), .exr (Image) or
/// .png (ColorMappedImage, HistogramPlot).
std::string sensorFileName(const sensors::SensorOutput& output);
/// An Image's numbers also as <name>.npy ((H, W) or (H, W, C) float32), for
/// readers without OpenEXR; its metadata lists it as files.npy.
std::string sensorArrayFileName(const sensors::SensorOutput& output);

}  // namespace tofsim::pipeline
