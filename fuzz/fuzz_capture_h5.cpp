// Bytes -> capture.h5 -> io::H5CaptureReader (output.format: hdf5; what
// `tofsim sense`, `tofsim compare` and SavedVolume read), every kind of read
// it offers (fuzz/CaptureH5Reads.h). Not in CI's runs: within seconds it
// finds faults inside libhdf5 1.10.8 itself (fuzz/README.md).
#include "CaptureH5Reads.h"
#include "FuzzFile.h"
#include "Hdf5AsanOptions.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = tofsim::fuzz::writeInput("capture.h5", data, size);
  try {
    tofsim::fuzz::readCaptureH5(path);
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
