#pragma once
// output.format: hdf5: a camera render's arrays as the datasets of one
// capture.h5 (tofsim/io/Hdf5Capture.h), in the staging folder like every
// output. The volumes stream in segment by segment (one block of chunks held
// per volume); the steady image, the depth and the sensors' arrays are added
// whole once written; commit() renames the file into place. Each dataset
// carries its metadata as attributes: `json` (the text of the JSON file that
// describes it: transient.json, the sensor output's <output>.json) and, where
// the JSON has them, `units`, `axes`, `channels`, `start_s`, `bin_width_s`
// and `bins`.
//
// Datasets: transient, direct, indirect, bounce<k> (H, W, T, C); steady
// (H, W, C); depth (H, W); sensors/<sensor>/<output> (the .npy's and .exr's
// arrays of sensors/<sensor>/). The axes' coordinates are HDF5 dimension
// scales (what netCDF-4 readers and xarray take as coordinates): y and x
// (pixel row and column), t (each bin's leading edge, s) and c (channel),
// attached to every dataset's axes they describe: the volumes', steady's,
// depth's, and a sensor array's axes of those names and lengths (t only on
// the render's own time axis).

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

class CaptureFile {
 public:
  /// threads: render.threads (0 = every core), compressing the volumes.
  CaptureFile(const std::filesystem::path& file, int threads);
  ~CaptureFile();
  CaptureFile(const CaptureFile&) = delete;
  CaptureFile& operator=(const CaptureFile&) = delete;

  /// A sink streaming the segments' `component` (FiniteSegments.h, static
  /// lifetime) into the (H, W, T, C) dataset `dataset`.
  capture::SegmentSink& volume(const std::string& dataset, std::string_view component,
                               int32_t width, int32_t height, int32_t bins);
  /// transient.json's text as the attributes of every volume.
  void describeVolumes(const std::string& metadataJson);
  /// steady (H, W, C) with the volumes' unit.
  void addSteady(const Image& steady);
  /// depth (H, W), metres.
  void addDepth(const Image& depth_m);
  /// The arrays of the sensor files `files` (relative to `directory`):
  /// each <output>.npy and <output>.exr as sensors/<sensor>/<output>, with
  /// its <output>.json.
  void addSensorFiles(const std::filesystem::path& directory,
                      const std::vector<std::string>& files);
  void commit();

 private:
  class VolumeSink;
  /// The scales y, x and c, written once; false when an image of another
  /// size came first (then `dataset` keeps its axes unscaled).
  bool pixelScales(std::size_t height, std::size_t width);
  /// Attaches y and x to axes 0 and 1 of `dataset` (height x width first)
  /// and the scales `more` (by name, "" for none) to the axes after them.
  void attachScales(const std::string& dataset, std::size_t height, std::size_t width,
                    const std::vector<std::string>& more);
  /// The scales of the sensor array `dataset` of `shape` described by
  /// `jsonText`: each axis its JSON names y, x, t or c, of the scale's length.
  void attachSensorScales(const std::string& dataset, const io::NpyShape& shape,
                          const std::string& jsonText);

  io::H5CaptureWriter writer_;
  std::vector<std::unique_ptr<VolumeSink>> volumes_;
  std::size_t height_ = 0, width_ = 0;  ///< of the y and x scales, once written
  std::string timeJson_;                ///< transient.json's time, once the t scale is written
};

}  // namespace tofsim::pipeline
