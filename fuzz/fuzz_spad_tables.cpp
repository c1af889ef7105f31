// Bytes -> a SPAD's table file (fuzz/SpadTablesInput.h): a TDC DNL (.csv or
// .npy), a dark count map (.npy) or an afterpulse delay table (.csv or
// .npy), read by config::loadRunConfig; a config that loads is run through
// the SPAD.
#include "ConfigFileInput.h"
#include "SpadTablesInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return tofsim::fuzz::fuzzConfigFile(data, size, tofsim::fuzz::writeSpadTablesInput,
                                      tofsim::fuzz::runSpadTables);
}
