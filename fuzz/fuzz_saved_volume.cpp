// Bytes -> a saved render (transient.json + transient.npy) -> loadSavedVolume
// (what `tofsim compare` reads) and SavedVolumeStream read in runs of 7
// pixels (what `tofsim sense` reads). The input is split at the
// first NUL byte: JSON before it, .npy after it (so both files mutate).
#include <cstring>

#include "FuzzFile.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const void* nul = std::memchr(data, 0, size);
  const size_t jsonSize = nul ? static_cast<const uint8_t*>(nul) - data : size;
  tofsim::fuzz::writeInput("transient.json", data, jsonSize);
  const size_t npyStart = nul ? jsonSize + 1 : size;
  tofsim::fuzz::writeInput("transient.npy", data + npyStart, size - npyStart);
  try {
    const tofsim::pipeline::SavedVolume saved =
        tofsim::pipeline::loadSavedVolume(tofsim::fuzz::workDir());
    const tofsim::TransientVolume& v = saved.volume;
    if (v.values().size() !=
        static_cast<size_t>(v.width()) * v.height() * v.bins() * v.channels()) {
      __builtin_trap();
    }
  } catch (const tofsim::InputError&) {
  }
  try {
    tofsim::pipeline::SavedVolumeStream stream(tofsim::fuzz::workDir(), {"direct"});
    std::size_t pixels = 0;
    while (const std::size_t run = stream.read(7)) {
      if (run > 7 || stream.firstPixel() != pixels || stream.values("transient") == nullptr) {
        __builtin_trap();
      }
      pixels += run;
    }
    if (pixels != stream.shape().pixelCount()) __builtin_trap();
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
