#pragma once
// Private to the config module: a table of (delay, value) rows a config
// names as a file, read and checked alike wherever one is named (a SPAD's
// afterpulse delay density, SpadTableFile.h; a material's measured
// scattering delay, ResponseTableFile.h): a float32 .npy of shape (n, 2) or
// a two-column .csv ('#' comments, a header line allowed), opened without
// following a link (io/FileBytes.h); at least 2 rows, delays finite, >= 0
// and increasing, values finite and >= 0 with a positive, finite area. Every
// bad file is an InputError located at the config's key, naming the file,
// its line (CSV) or row (.npy) and the column.

#include <string>
#include <vector>

#include "ConfigNode.h"

namespace tofsim::config {

/// How errors name the table's parts.
struct DelayTableWords {
  std::string table;      ///< "an afterpulse delay table" (its .npy's form is said after it)
  std::string value;      ///< the second column, "density"
  std::string delayNote;  ///< why delays are >= 0
  std::string valueNote;  ///< why values are >= 0
  std::string delayUnit = "s";
};

struct DelayRows {
  std::string file;  ///< absolute
  std::vector<double> delays;  ///< in the file's unit (DelayTableWords::delayUnit)
  std::vector<double> values;
};

/// The rows of the file that key `key` of node n names.
DelayRows readDelayTable(const ConfigNode& n, const char* key, const DelayTableWords& words);

}  // namespace tofsim::config
