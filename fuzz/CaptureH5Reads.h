#pragma once
// What fuzz_capture_h5 reads of a capture.h5 (output.format: hdf5), shared
// with the regression test (tests/hardening/FuzzRegressionTest.cpp) so both
// read an input alike: for each dataset a render writes, its shape, its
// attributes, the whole array, one pixel's histogram, one time slice and runs
// of pixels as SavedVolumeStream reads them. Every read must return the size
// its shape promises (else a trap) or throw InputError; a dataset that fails
// does not stop the next.
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/io/Hdf5Capture.h"
#include "tofsim/util/Error.h"

namespace tofsim::fuzz {

inline void readCaptureDataset(const io::H5CaptureReader& reader, const std::string& name) {
  if (!reader.has(name)) return;
  const io::NpyShape shape = reader.shape(name);
  (void)reader.stringAttribute(name, "json");
  (void)reader.stringAttribute(name, "units");
  if (reader.read(name).data.size() != io::elementCount(shape)) __builtin_trap();
  if (shape.size() < 2) return;  // readPixels' precondition, as SavedVolume checks it

  // One pixel's histogram: (0, 0), every value of the axes after the first two.
  io::NpyShape start(shape.size(), 0), count = shape;
  count[0] = std::min<std::size_t>(count[0], 1);
  count[1] = std::min<std::size_t>(count[1], 1);
  if (reader.readSlab(name, start, count).size() != io::elementCount(count)) __builtin_trap();
  if (shape.size() >= 3 && shape[2] > 0) {  // the last time slice of every pixel
    start[2] = shape[2] - 1;
    count = shape;
    count[2] = 1;
    if (reader.readSlab(name, start, count).size() != io::elementCount(count)) __builtin_trap();
  }

  // Runs of up to 7 pixels as SavedVolumeStream reads them (the end of a
  // row, whole rows, the start of one): the first two, one from the middle
  // and the last; not all of them, so a file of many pixels stays quick.
  const std::size_t pixels = shape[0] * shape[1];
  const std::size_t inner = pixels == 0 ? 0 : io::elementCount(shape) / pixels;
  const std::size_t last = pixels - std::min<std::size_t>(pixels, 7);
  std::vector<float> run;
  for (const std::size_t first : {std::size_t{0}, std::size_t{7}, pixels / 2, last}) {
    if (first >= pixels) continue;
    const std::size_t n = std::min<std::size_t>(7, pixels - first);
    run.assign(n * inner, 0.0f);
    reader.readPixels(name, first, n, run.data());
  }
}

/// Opens `file` (InputError when it cannot) and reads the volumes, the images
/// and a sensor's array (a dataset in groups).
inline void readCaptureH5(const std::filesystem::path& file) {
  const io::H5CaptureReader reader(file);
  for (const char* name : {"transient", "direct", "steady", "depth", "sensors/spad/spad_counts"}) {
    try {
      readCaptureDataset(reader, name);
    } catch (const InputError&) {
    }
  }
}

}  // namespace tofsim::fuzz
