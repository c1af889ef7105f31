// Bytes -> .hdf5 file -> io::readTalCapture (y-tal's NLOS capture layout).
// A file either reads with every field's size matching its shape, or throws
// InputError; HDF5's own parser runs under the sanitizers too.
#include <functional>
#include <numeric>

#include "FuzzFile.h"
#include "Hdf5AsanOptions.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/util/Error.h"

namespace {
std::size_t product(const std::vector<std::size_t>& shape) {
  return std::accumulate(shape.begin(), shape.end(), std::size_t(1), std::multiplies<>());
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = tofsim::fuzz::writeInput("input.hdf5", data, size);
  try {
    const tofsim::io::TalCapture c = tofsim::io::readTalCapture(path);
    if (c.H.size() != product(c.H_shape)) __builtin_trap();
    if (c.sensor_grid.xyz.size() != product(c.sensor_grid.shape)) __builtin_trap();
    if (c.laser_grid.xyz.size() != product(c.laser_grid.shape)) __builtin_trap();
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
