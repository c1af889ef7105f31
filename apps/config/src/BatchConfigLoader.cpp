// Expands a batch file into runs. Order: the sweep first, then `runs:`.
// Sweep: the cartesian product of the `product:` keys in file order (the
// first key varies slowest), times the `zip:` lists advanced together (the
// zip group is the innermost, fastest varying axis). Sweep run i is named
// "run%04d" plus a short suffix of its values; explicit runs take their
// `name` (or "run%04d"). Indices count all runs, so names stay stable when
// only the explicit list grows.

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cstdio>
#include <map>

#include "ConfigNode.h"
#include "tofsim/config/BatchConfig.h"

namespace tofsim::config {

namespace {

struct Axis {
  std::vector<std::string> keys;                 // one key, or the zipped keys
  std::vector<std::vector<std::string>> values;  // values[position][key]
};

std::string flowText(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetSeqFormat(YAML::Flow);
  out.SetMapFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

std::vector<std::string> valuesOf(const ConfigNode& list) {
  if (!list.isSequence()) list.fail("must be a list of values to sweep");
  std::vector<std::string> values;
  for (const ConfigNode& v : list.elements()) values.push_back(flowText(v.yaml()));
  if (values.empty()) list.fail("must not be empty");
  return values;
}

// Marks a whole subtree as read: its keys are config key paths and values
// (which may hold mappings, e.g. a sensor), checked later by loadRunConfig,
// not by the batch parser.
void markAll(const ConfigNode& node) {
  if (node.isSequence()) {
    for (const ConfigNode& e : node.elements()) markAll(e);
  } else if (node.isMap()) {
    for (const std::string& key : node.keys()) markAll(node.child(key));
  }
}

std::vector<Override> setOf(const ConfigNode& node) {
  if (!node.isMap()) node.fail("must be a mapping of key.path: value");
  std::vector<Override> out;
  for (const std::string& key : node.keys()) {
    markAll(node.child(key));
    out.push_back(Override{key, flowText(node.child(key).yaml())});
  }
  return out;
}

std::vector<Axis> sweepAxes(const ConfigNode& sweep) {
  std::vector<Axis> axes;
  if (!sweep.isMap()) sweep.fail("must be a mapping with product: and/or zip:");
  if (const auto product = sweep.optionalChild("product")) {
    if (!product->isMap()) product->fail("must map config keys to lists of values");
    for (const std::string& key : product->keys()) {
      axes.push_back(Axis{{key}, {}});
      for (const std::string& v : valuesOf(product->child(key))) axes.back().values.push_back({v});
    }
    markAll(*product);
  }
  if (const auto zip = sweep.optionalChild("zip")) {
    if (!zip->isMap()) zip->fail("must map config keys to lists of equal length");
    Axis axis;
    std::string firstKey;
    for (const std::string& key : zip->keys()) {
      const std::vector<std::string> values = valuesOf(zip->child(key));
      if (axis.keys.empty()) {
        axis.values.resize(values.size());
        firstKey = key;
      } else if (values.size() != axis.values.size()) {
        zip->failKey(key, "zip lists must have equal length (" + std::to_string(values.size()) +
                              " here, " + std::to_string(axis.values.size()) + " in " + firstKey +
                              ")");
      }
      axis.keys.push_back(key);
      for (std::size_t i = 0; i < values.size(); ++i) axis.values[i].push_back(values[i]);
    }
    markAll(*zip);
    if (!axis.keys.empty()) axes.push_back(std::move(axis));
  }
  return axes;
}

// "sensors.0.jitter_fwhm" = "30 ps" -> "jitter_fwhm-30ps": the last key part
// and the value with everything but [A-Za-z0-9.,+-] dropped.
std::string suffixPart(const Override& o) {
  const std::size_t dot = o.keyPath.rfind('.');
  std::string text = (dot == std::string::npos ? o.keyPath : o.keyPath.substr(dot + 1)) + "-";
  for (char c : o.value) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == ',' ||
                      c == '+' || c == '-' || c == '_';
    if (keep) text += c;
  }
  return text;
}

std::string runName(std::size_t index, const std::vector<Override>& varied) {
  char base[16];
  std::snprintf(base, sizeof base, "run%04zu", index);
  std::string name = base;
  for (const Override& o : varied) name += "_" + suffixPart(o);
  constexpr std::size_t kMaxName = 80;  // well under NAME_MAX, readable in a listing
  if (name.size() > kMaxName) name.resize(kMaxName);
  return name;
}

bool plainName(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name != "base" &&
         name.find_first_not_of(
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
             "0123456789_.,+-") == std::string::npos;
}

}  // namespace

BatchConfig loadBatchConfig(const std::filesystem::path& file, const std::vector<Override>& extra) {
  const YAML::Node yaml = loadYamlFile(file.string());
  if (!yaml.IsMap())
    throw InputError(FileLoc{file.string(), 1, 1}, "", "a batch must be a mapping");
  const ConfigNode root(yaml, file.string());
  BatchConfig batch;
  batch.batch_file = file;
  batch.base_config = (file.parent_path() / root.requireString("base")).lexically_normal();
  if (!std::filesystem::exists(batch.base_config)) {
    root.failKey("base", "base config not found: " + batch.base_config.string());
  }
  batch.output_root =
      (file.parent_path() / root.getString("output", "out/batch")).lexically_normal();
  std::vector<Override> common;
  if (const auto set = root.optionalChild("set")) common = setOf(*set);

  std::vector<Axis> axes;
  if (const auto sweep = root.optionalChild("sweep")) axes = sweepAxes(*sweep);
  std::size_t combinations = axes.empty() ? 0 : 1;
  for (const Axis& a : axes) combinations *= a.values.size();
  for (std::size_t i = 0; i < combinations; ++i) {
    BatchRun run;
    run.index = i;
    // Mixed-radix digits of i, the last axis fastest.
    std::vector<std::size_t> digit(axes.size());
    std::size_t rest = i;
    for (std::size_t a = axes.size(); a-- > 0;) {
      digit[a] = rest % axes[a].values.size();
      rest /= axes[a].values.size();
    }
    for (std::size_t a = 0; a < axes.size(); ++a) {
      for (std::size_t k = 0; k < axes[a].keys.size(); ++k) {
        run.varied.push_back(Override{axes[a].keys[k], axes[a].values[digit[a]][k]});
      }
    }
    run.name = runName(i, run.varied);
    run.overrides = common;
    run.overrides.insert(run.overrides.end(), run.varied.begin(), run.varied.end());
    batch.runs.push_back(std::move(run));
  }

  std::map<std::string, std::size_t> seen;
  for (const BatchRun& r : batch.runs) seen[r.name] = r.index;
  if (const auto runs = root.optionalChild("runs")) {
    for (const ConfigNode& entry : runs->elements()) {
      BatchRun run;
      run.index = batch.runs.size();
      run.name = entry.getString("name", runName(run.index, {}));
      if (!plainName(run.name)) {
        entry.failKey(
            "name", "must be letters, digits, '_', '-', '.', ',' or '+' (got '" + run.name + "')");
      }
      if (seen.count(run.name)) entry.failKey("name", "run name '" + run.name + "' is used twice");
      seen[run.name] = run.index;
      if (const auto set = entry.optionalChild("set")) run.varied = setOf(*set);
      run.overrides = common;
      run.overrides.insert(run.overrides.end(), run.varied.begin(), run.varied.end());
      batch.runs.push_back(std::move(run));
    }
  }
  if (batch.runs.empty()) {
    // No sweep, no runs: the base config (with `set`) is the one run.
    BatchRun run;
    run.name = "run0000";
    run.overrides = common;
    batch.runs.push_back(std::move(run));
  }
  for (BatchRun& run : batch.runs)
    run.overrides.insert(run.overrides.end(), extra.begin(), extra.end());
  root.reportUnusedKeys();
  return batch;
}

void validateBatch(const BatchConfig& batch) {
  std::string errors;
  std::size_t failed = 0;
  for (const BatchRun& run : batch.runs) {
    try {
      loadRunConfig(batch.base_config, run.overrides);
    } catch (const std::exception& e) {
      errors += "\n  run " + run.name + ": " + e.what();
      ++failed;
    }
  }
  if (failed > 0) {
    throw InputError(batch.batch_file.string() + ": " + std::to_string(failed) + " of " +
                     std::to_string(batch.runs.size()) + " run(s) have invalid configs:" + errors);
  }
}

}  // namespace tofsim::config
