#pragma once
// The products of a camera render, each named once: what files it writes,
// how large they will be, and which writer makes them. The render run writes
// what renderProducts lists, in that order, and lists those files; the size
// estimate (OutputEstimate.h) sums the same table; transient.json names the
// files a reader looks for from it; readers of a saved render (`tofsim
// sense`, the Python module) open them by these names.

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/OutputFileNames.h"

namespace tofsim::pipeline {

/// Which writer makes a product (RenderRun.cpp dispatches on it).
enum class Writer {
  Volume,    ///< a component streamed as it is rendered: to .npy (VolumeFileSink) or capture.h5
  Capture,   ///< capture.h5 (output.format: hdf5), committed after the sensors (CaptureFile.h)
  Steady,    ///< the volume summed over time: EXR and tone-mapped PNG
  Depth,     ///< the camera-to-surface distance: EXR, .npy and colour-mapped PNG
  Frames,    ///< one EXR per time bin, from the bin-major copy
  Video,     ///< transient.mp4 and/or the frame PNGs, from the bin-major copy
  Metadata,  ///< transient.json
};

struct OutputProduct {
  Writer writer;
  /// Writer::Volume: the segment component it streams (FiniteSegments.h).
  std::string_view component;
  /// Writer::Volume: its name without ".npy", the dataset of capture.h5.
  std::string dataset;
  std::vector<std::string> files;  ///< written, in order, relative to the output folder
  std::vector<OutputItem> sizes;   ///< its lines of the size estimate
};

/// What `config` writes, in writing order (sensors, the effective config
/// and the manifest follow them: they are not the camera's products).
std::vector<OutputProduct> renderProducts(const config::RunConfig& config);

/// Bytes of one volume's floats (H W T C float32, no header).
std::uintmax_t volumeBytes(const config::RunConfig& config);

/// transient.json's "files": the volume (transient.npy, or capture.h5 with
/// output.format: hdf5), the steady picture and the depth a reader looks
/// for, by role.
std::vector<std::pair<std::string, std::string>> metadataFiles(const config::OutputConfig& out);

}  // namespace tofsim::pipeline
