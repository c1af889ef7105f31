#pragma once
// Private to the SPAD model: the per-pixel images read off each pixel's
// histogram (total counts, peak and Coates depths, the estimators' depth,
// confidence and returns; SpadEstimators.h), filled pixel by pixel from any
// thread, and the fixed-pattern maps, as the model's outputs.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "SpadEstimators.h"
#include "SpadFlimImages.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/SpadPixelMaps.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors::detail {

/// An (H, W) Image output.
SensorOutput spadImage(const std::string& name, int32_t H, int32_t W, std::vector<float> data,
                       const std::string& unit, const std::string& description);

class SpadImages {
 public:
  /// `kernel`: the instrument's, for the matched filter; deadBins the
  /// detector's dead time in TDC bins (Coates' correction takes it).
  SpadImages(const SpadParams& p, const TimeAxis& axis, const BinKernel& kernel, int32_t deadBins,
             int32_t height, int32_t width);

  /// Reused buffers (one per thread).
  struct Scratch {
    std::vector<double> lossless;
    SpadEstimator::Scratch estimates;
    FlimFitter::Scratch flim;
  };
  /// Pixel px's values from its histogram `h` (any thread, each pixel once).
  void pixel(std::size_t px, const std::vector<double>& h, Scratch& s) const;

  /// Appends the depth Images (with point clouds), spad_intensity and
  /// spad_confidence, ColorMappedImages of those five, the three returns'
  /// depths and intensities and spad_returns (runSpad's order); then, with
  /// SpadParams::flim, the FLIM outputs (SpadFlimImages.h).
  void finish(std::vector<SensorOutput>& outputs);

 private:
  SensorOutput depthImage(const std::string& name, std::vector<float> data,
                          const std::string& description, SensorOutput::PointCloud cloud) const;

  const int32_t height_, width_;
  const int64_t cycles_;
  const int64_t stops_;
  const int32_t deadBins_;
  const bool synchronous_;
  const std::string colormap_;
  const TimeAxis axis_;
  const SpadEstimator estimator_;
  std::optional<SpadFlimImages> flim_;  ///< with SpadParams::flim
  // Written by pixel() from several threads, each pixel by one only.
  mutable std::vector<float> depthPeak_, depthCoates_, intensity_, depthMatched_, confidence_,
      returns_;
  mutable std::array<std::vector<float>, 3> returnDepth_,
      returnIntensity_;  // first, strongest, last
};

/// Appends spad_pde_map and spad_dcr_map (with a fixed pattern) and
/// spad_gate_skew_map (with gate skew).
void appendSpadMapImages(const SpadParams& p, const SpadPixelMaps& maps, int32_t H, int32_t W,
                         std::vector<SensorOutput>& outputs);

}  // namespace tofsim::sensors::detail
