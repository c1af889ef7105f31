// Writes the confocal and the exhaustive sample capture (TalCaptureSamples.h)
// to the two paths given, for tal_capture_h5py.py to check with h5py.
#include <cstdio>
#include <exception>

#include "io/TalCaptureSamples.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s CONFOCAL.hdf5 EXHAUSTIVE.hdf5\n", argv[0]);
    return 2;
  }
  try {
    tofsim::io::writeTalCapture(argv[1], tofsim::io::test::confocalSample());
    tofsim::io::writeTalCapture(argv[2], tofsim::io::test::exhaustiveSample());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
