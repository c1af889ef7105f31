// A batch's runs, made on demand. Order: the sweep first, then `runs:`.
// Sweep: the cartesian product of the `product:` keys in file order (the
// first key varies slowest), times the `zip:` lists advanced together (the
// zip group is the innermost, fastest varying axis). Sweep run i is named
// "run%04d" plus a short suffix of its values; explicit runs take their
// `name` (or "run%04d"). Indices count all runs, so names stay stable when
// only the explicit list grows.

#include <cctype>
#include <cstdio>

#include "BatchExpansion.h"
#include "tofsim/config/BatchConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {

namespace {

// Only the characters a run name may have (letters, digits, `.,+-_`).
std::string plainPart(const std::string& text) {
  std::string kept;
  for (char c : text) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == ',' ||
                      c == '+' || c == '-' || c == '_';
    if (keep) kept += c;
  }
  return kept;
}

// "sensors.0.jitter_fwhm" = "30 ps" -> "jitter_fwhm-30ps": the last key part
// and the value, each with every other character dropped (a key is checked
// only when the run's config loads, after the name is made: fuzz_batch found
// a '/' kept from one).
std::string suffixPart(const Override& o) {
  const std::size_t dot = o.keyPath.rfind('.');
  return plainPart(dot == std::string::npos ? o.keyPath : o.keyPath.substr(dot + 1)) + "-" +
         plainPart(o.value);
}

}  // namespace

std::string batchRunName(std::size_t index, const std::vector<Override>& varied) {
  char base[32];
  std::snprintf(base, sizeof base, "run%04zu", index);
  std::string name = base;
  for (const Override& o : varied) {
    name += "_" + suffixPart(o);
    if (name.size() > kMaxRunName) break;  // (a long value is cut below anyway)
  }
  if (name.size() > kMaxRunName) name.resize(kMaxRunName);
  return name;
}

std::size_t BatchConfig::runCount() const {
  const std::size_t runs = sweepRuns + listed.size();
  return runs == 0 ? 1 : runs;  // no sweep, no runs: the base config (with `set`)
}

BatchRun BatchConfig::run(std::size_t index) const {
  TOFSIM_CHECK(index < runCount());
  BatchRun run;
  if (index < sweepRuns) {
    run.index = index;
    // Mixed-radix digits of the index, the last axis fastest.
    std::vector<std::size_t> digit(sweep.size());
    std::size_t rest = index;
    for (std::size_t a = sweep.size(); a-- > 0;) {
      digit[a] = rest % sweep[a].values.size();
      rest /= sweep[a].values.size();
    }
    for (std::size_t a = 0; a < sweep.size(); ++a) {
      for (std::size_t k = 0; k < sweep[a].keys.size(); ++k) {
        run.varied.push_back(Override{sweep[a].keys[k], sweep[a].values[digit[a]][k]});
      }
    }
    run.name = batchRunName(index, run.varied);
  } else if (!listed.empty()) {
    run = listed[index - sweepRuns];
  } else {
    run.name = batchRunName(0, {});
  }
  run.overrides = common;
  run.overrides.insert(run.overrides.end(), run.varied.begin(), run.varied.end());
  run.overrides.insert(run.overrides.end(), extra.begin(), extra.end());
  return run;
}

}  // namespace tofsim::config
