// Bytes -> .npy file -> io::readNpy.
#include "FuzzFile.h"
#include "tofsim/io/Npy.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = tofsim::fuzz::writeInput("input.npy", data, size);
  try {
    const tofsim::io::NpyArray array = tofsim::io::readNpy(path);
    if (array.data.size() != tofsim::io::elementCount(array.shape)) __builtin_trap();
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
