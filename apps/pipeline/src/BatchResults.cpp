#include "tofsim/pipeline/BatchResults.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::optional<json> readJson(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    return json::parse(in);
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

// One image's numbers: mean and valid fraction, and mean |x| when signed.
json imageSummary(const fs::path& npy, bool isSigned) {
  const io::NpyArray a = io::readNpy(npy);
  double sum = 0.0, sumAbs = 0.0;
  std::size_t finite = 0;
  for (float v : a.data) {
    if (!std::isfinite(v)) continue;
    ++finite;
    sum += v;
    sumAbs += std::fabs(v);
  }
  const auto mean = [&](double s) { return finite ? json(s / static_cast<double>(finite)) : json(); };
  json out = {{"mean", mean(sum)},
              {"valid_fraction", a.data.empty() ? json() : json(static_cast<double>(finite) /
                                                                static_cast<double>(a.data.size()))}};
  if (isSigned) out["mean_abs"] = mean(sumAbs);
  return out;
}

// {sensor: {output: summary}} of a finished run's folder, names sorted.
json sensorSummaries(const fs::path& dir) {
  json sensors = json::object();
  std::error_code ec;
  if (!fs::is_directory(dir / "sensors", ec)) return sensors;
  std::vector<fs::path> metadata;
  for (const auto& sensor : fs::directory_iterator(dir / "sensors", ec)) {
    if (!sensor.is_directory()) continue;
    for (const auto& f : fs::directory_iterator(sensor.path(), ec)) {
      if (f.path().extension() == ".json") metadata.push_back(f.path());
    }
  }
  std::sort(metadata.begin(), metadata.end());
  for (const fs::path& file : metadata) {
    const std::optional<json> doc = readJson(file);
    if (!doc || doc->value("kind", "") != "image") continue;
    const auto files = doc->find("files");
    if (files == doc->end() || !files->contains("npy")) continue;
    const fs::path npy = file.parent_path() / (*files)["npy"].get<std::string>();
    if (!fs::exists(npy, ec)) continue;
    sensors[file.parent_path().filename().string()][file.stem().string()] =
        imageSummary(npy, doc->value("signed", false));
  }
  return sensors;
}

json runRow(const config::BatchConfig& batch, const BatchRunResult& r) {
  json swept = json::object();
  for (const config::Override& o : batch.run(r.index).varied) swept[o.keyPath] = o.value;
  json row = {{"run", r.name},
              {"swept", swept},
              {"directory", r.directory.string()},
              {"status", batchRunStatusName(r.status)},
              {"seconds", r.seconds},
              {"render_from", json()},
              {"sensors", json::object()}};
  const bool finished = r.status == BatchRunStatus::Done || r.status == BatchRunStatus::Skipped;
  if (!finished) return row;
  try {
    const ManifestRecord manifest = readManifest(r.directory);
    row["render_from"] = manifest.renderFrom.empty() ? r.name : manifest.renderFrom;
  } catch (const InputError&) {  // no readable manifest: no render to name
  }
  try {
    row["sensors"] = sensorSummaries(r.directory);
  } catch (const InputError& e) {  // a sensor's file unreadable: the row says so
    row["error"] = e.what();
  }
  return row;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csvValue(const json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return csvField(v.get<std::string>());
  return csvField(v.dump());
}

// Columns: the fixed ones, every swept key, then every sensor number, each in
// the order first met.
std::string csvTable(const json& rows) {
  std::vector<std::string> swept, numbers;
  const auto add = [](std::vector<std::string>& list, const std::string& name) {
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  };
  for (const json& row : rows) {
    for (const auto& [key, value] : row["swept"].items()) add(swept, key);
    for (const auto& [sensor, outputs] : row["sensors"].items()) {
      for (const auto& [output, stats] : outputs.items()) {
        for (const auto& [stat, value] : stats.items()) {
          add(numbers, sensor + "/" + output + ":" + stat);
        }
      }
    }
  }
  const std::vector<std::string> fixed = {"run", "status", "seconds", "directory", "render_from"};
  std::string out;
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cells[i];
    out += "\n";
  };
  std::vector<std::string> header;
  for (const std::string& c : fixed) header.push_back(csvField(c));
  for (const std::string& c : swept) header.push_back(csvField(c));
  for (const std::string& c : numbers) header.push_back(csvField(c));
  line(header);
  for (const json& row : rows) {
    std::vector<std::string> cells;
    for (const std::string& c : fixed) cells.push_back(csvValue(row[c]));
    for (const std::string& c : swept) {
      cells.push_back(row["swept"].contains(c) ? csvValue(row["swept"][c]) : "");
    }
    for (const std::string& c : numbers) {
      const std::size_t slash = c.find('/'), colon = c.rfind(':');
      const json::json_pointer at("/" + c.substr(0, slash) + "/" +
                                  c.substr(slash + 1, colon - slash - 1) + "/" +
                                  c.substr(colon + 1));
      cells.push_back(row["sensors"].contains(at) ? csvValue(row["sensors"][at]) : "");
    }
    line(cells);
  }
  return out;
}

}  // namespace

std::string batchResultsStem(const BatchOptions& options) {
  if (options.shardCount == 1) return "results";
  return "results-" + std::to_string(options.shardIndex) + "-of-" +
         std::to_string(options.shardCount);
}

fs::path writeBatchResults(const config::BatchConfig& batch, const BatchOptions& options,
                           const BatchSummary& summary) {
  json rows = json::array();
  for (const BatchRunResult& r : summary.runs) rows.push_back(runRow(batch, r));
  const json doc = {{"format", "tofsim batch results"},
                    {"batch", fs::absolute(batch.batch_file).string()},
                    {"shard", std::to_string(options.shardIndex) + "/" +
                                  std::to_string(options.shardCount)},
                    {"runs", rows}};
  fs::create_directories(batch.output_root);
  const fs::path stem = batch.output_root / batchResultsStem(options);
  writeFileAtomically(stem.string() + ".json", doc.dump(2) + "\n");
  const fs::path csv = stem.string() + ".csv";
  writeFileAtomically(csv, csvTable(rows));
  return csv;
}

}  // namespace tofsim::pipeline
