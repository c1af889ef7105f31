// Reads a batch file: its base, `set:`, the sweep's axes (counted, not
// expanded: BatchExpansion.cpp makes the runs on demand) and the `runs:`
// list, with their names checked as folder names.

#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <map>

#include "BatchExpansion.h"
#include "ConfigNode.h"
#include "tofsim/config/BatchConfig.h"
#include "tofsim/util/FolderPath.h"

namespace tofsim::config {

namespace {

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
    if (!node.has(key)) {  // `key: null` sets null (e.g. a capture_order to derive)
      node.markUsed(key);
      out.push_back(Override{key, "null"});
      continue;
    }
    markAll(node.child(key));
    out.push_back(Override{key, flowText(node.child(key).yaml())});
  }
  return out;
}

std::vector<SweepAxis> sweepAxes(const ConfigNode& sweep) {
  std::vector<SweepAxis> axes;
  if (!sweep.isMap()) sweep.fail("must be a mapping with product: and/or zip:");
  if (const auto product = sweep.optionalChild("product")) {
    if (!product->isMap()) product->fail("must map config keys to lists of values");
    for (const std::string& key : product->keys()) {
      axes.push_back(SweepAxis{{key}, {}});
      for (const std::string& v : valuesOf(product->child(key))) axes.back().values.push_back({v});
    }
    markAll(*product);
  }
  if (const auto zip = sweep.optionalChild("zip")) {
    if (!zip->isMap()) zip->fail("must map config keys to lists of equal length");
    SweepAxis axis;
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

// The number of runs of the axes, or a located error at `sweep` when it is
// over kMaxBatchRuns (counted without overflow: 32^4 runs or 10^30).
std::size_t sweepRunCount(const ConfigNode& sweep, const std::vector<SweepAxis>& axes) {
  std::size_t runs = 1;
  double product = 1.0;  // the count when it overflows
  std::string factors;
  for (const SweepAxis& a : axes) {
    const std::size_t n = a.values.size();
    product *= static_cast<double>(n);
    runs = runs > kMaxBatchRuns ? runs : runs * n;  // past the cap: the count is not used
    std::string keys = a.keys[0];
    if (a.keys.size() > 1) keys = "zip " + keys + " +" + std::to_string(a.keys.size() - 1);
    factors += (factors.empty() ? "" : " x ") + std::to_string(n) + " (" + keys + ")";
  }
  if (product > static_cast<double>(kMaxBatchRuns)) {
    char total[32];
    std::snprintf(total, sizeof total, product < 1e15 ? "%.0f" : "%.3g", product);
    sweep.fail("expands to " + factors + " = " + total + " runs, more than the " +
               std::to_string(kMaxBatchRuns) +
               " a batch may have: sweep fewer values, or split it into several batches");
  }
  return runs;
}

// A run's name is its folder's: plain characters, not hidden (the batch's own
// lock files are .<run>.lock beside the run folders) and of a listable length.
void checkRunName(const ConfigNode& entry, const std::string& name) {
  const std::string shown = name.size() > 40 ? name.substr(0, 40) + "..." : name;
  const auto fail = [&](const std::string& rule) {
    entry.failKey("name", "run name '" + shown + "' " + rule);
  };
  if (name.size() > kMaxRunName) {
    fail("is " + std::to_string(name.size()) + " characters long: at most " +
         std::to_string(kMaxRunName));
  }
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                             "0123456789_.,+-") != std::string::npos) {
    fail("must be letters, digits, '_', '-', '.', ',' or '+'");
  }
  if (name[0] == '.') {
    fail("must not start with '.' (a hidden folder; .<run>.lock files are the batch's own)");
  }
  if (name == "base") fail("is reserved");
}

// Whether an explicit name is one the sweep gives: "run<digits>..." names
// sweep run <digits> at most, so one comparison, not a list of every name.
bool sweepHasName(const BatchConfig& batch, const std::string& name) {
  if (name.rfind("run", 0) != 0) return false;
  const std::size_t end = name.find_first_not_of("0123456789", 3);
  const std::string digits = name.substr(3, end == std::string::npos ? end : end - 3);
  if (digits.empty() || digits.size() > 9) return false;
  const std::size_t index = std::stoul(digits);
  return index < batch.sweepRuns && batch.run(index).name == name;
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
  std::error_code ec;  // (a name too long for the file system is an error, not an exception)
  if (!std::filesystem::exists(batch.base_config, ec)) {
    root.failKey("base", (ec ? ec.message() + ": " : "base config not found: ") +
                             batch.base_config.string());
  }
  batch.output_root =
      (file.parent_path() / root.getString("output", "out/batch")).lexically_normal();
  const std::string outputProblem = folderPathProblem(batch.output_root);
  if (!outputProblem.empty()) root.failKey("output", outputProblem);
  if (const auto set = root.optionalChild("set")) batch.common = setOf(*set);
  batch.extra = extra;

  if (const auto sweep = root.optionalChild("sweep")) {
    batch.sweep = sweepAxes(*sweep);
    if (!batch.sweep.empty()) batch.sweepRuns = sweepRunCount(*sweep, batch.sweep);
  }
  if (const auto runs = root.optionalChild("runs")) {
    if (!runs->isSequence()) runs->fail("must be a list of runs (name:, set:)");
    std::map<std::string, std::size_t> seen;  // the listed runs' names
    for (const ConfigNode& entry : runs->elements()) {
      if (batch.sweepRuns + batch.listed.size() >= kMaxBatchRuns) {
        runs->fail("the sweep and the runs listed make more than the " +
                   std::to_string(kMaxBatchRuns) + " runs a batch may have");
      }
      BatchRun run;
      run.index = batch.sweepRuns + batch.listed.size();
      run.name = entry.getString("name", batchRunName(run.index, {}));
      checkRunName(entry, run.name);
      if (seen.count(run.name) || sweepHasName(batch, run.name)) {
        entry.failKey("name", "run name '" + run.name + "' is used twice");
      }
      seen[run.name] = run.index;
      if (const auto set = entry.optionalChild("set")) run.varied = setOf(*set);
      batch.listed.push_back(std::move(run));
    }
  }
  root.reportUnusedKeys();
  return batch;
}

void validateBatch(const BatchConfig& batch,
                   const std::function<void(std::size_t, std::size_t)>& progress) {
  constexpr std::size_t kListed = 20;  // failing runs whose errors the message shows
  std::string errors;
  std::size_t failed = 0;
  const std::size_t runs = batch.runCount();
  for (std::size_t i = 0; i < runs; ++i) {
    const BatchRun run = batch.run(i);
    try {
      loadRunConfig(batch.base_config, run.overrides);
    } catch (const InputError& e) {
      if (++failed <= kListed) errors += "\n  run " + run.name + ": " + e.what();
    }
    if (progress) progress(i + 1, runs);
  }
  if (failed > kListed) errors += "\n  ... and " + std::to_string(failed - kListed) + " more";
  if (failed > 0) {
    throw InputError(batch.batch_file.string() + ": " + std::to_string(failed) + " of " +
                     std::to_string(runs) + " run(s) have invalid configs:" + errors);
  }
}

}  // namespace tofsim::config
