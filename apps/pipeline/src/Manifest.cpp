#include "tofsim/pipeline/Manifest.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "tofsim/io/FileBytes.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Hash.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

namespace {

// Not outputs: the log belongs to the batch, the manifest describes the rest,
// and dot-files (lock files, staging folders) are the writers' bookkeeping.
bool isOutput(const std::string& relative) {
  if (relative == kManifestName || relative == kRunLogName) return false;
  for (const fs::path& part : fs::path(relative)) {
    if (part.string().rfind('.', 0) == 0) return false;
  }
  return true;
}

// The manifest's inputs, each "" when it is not a string (it then differs).
std::optional<RunContentKey> readInputs(const nlohmann::json& doc) {
  const auto inputs = doc.find("inputs");
  if (inputs == doc.end() || !inputs->is_object()) return std::nullopt;
  const auto text = [&](const char* key) {
    const auto it = inputs->find(key);
    return it != inputs->end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  return RunContentKey{text("config"), text("scene"), text("version"), text("render"),
                       text("sense")};
}

std::string staleReason(const ManifestRecord& manifest, const RunContentKey& expected) {
  if (!manifest.inputs) return "stale (no inputs recorded)";
  if (manifest.inputs->config != expected.config) return "stale (config changed)";
  if (manifest.inputs->scene != expected.scene) return "stale (scene changed)";
  if (manifest.inputs->version != expected.version) return "stale (version changed)";
  return "";
}

// "" when every listed file is there with its size (and checksum).
std::string missingOutput(const ManifestRecord& manifest, const fs::path& directory, bool verify) {
  for (const ManifestEntry& f : manifest.files) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(directory / f.path, ec);
    if (ec) return "missing " + f.path;
    if (size != f.bytes) return "size changed: " + f.path;
    if (verify && hex64(fnv1a64File(directory / f.path)) != f.fnv1a64) {
      return "checksum changed: " + f.path;
    }
  }
  return "";
}

}  // namespace

std::vector<ManifestEntry> writeManifest(const fs::path& directory, const std::string& runName,
                                         const std::vector<std::string>& files,
                                         const RunContentKey& inputs,
                                         const std::string& renderFrom) {
  std::vector<ManifestEntry> entries;
  for (const std::string& f : files) {
    const std::string rel = fs::path(f).generic_string();
    if (!isOutput(rel)) continue;
    entries.push_back({rel, fs::file_size(directory / rel), hex64(fnv1a64File(directory / rel))});
  }
  // Sorted, the manifest of the same outputs is the same bytes.
  std::sort(entries.begin(), entries.end(),
            [](const ManifestEntry& a, const ManifestEntry& b) { return a.path < b.path; });
  entries.erase(
      std::unique(entries.begin(), entries.end(),
                  [](const ManifestEntry& a, const ManifestEntry& b) { return a.path == b.path; }),
      entries.end());
  nlohmann::json list = nlohmann::json::array();
  for (const ManifestEntry& m : entries) {
    list.push_back({{"path", m.path}, {"bytes", m.bytes}, {"fnv1a64", m.fnv1a64}});
  }
  const nlohmann::json doc = {
      {"run", runName},
      {"hash", "fnv1a64"},
      {"inputs",
       {{"config", inputs.config},
        {"scene", inputs.scene},
        {"version", inputs.version},
        {"render", inputs.render},
        {"sense", inputs.sense}}},
      {"render", {{"key", inputs.render}, {"from", renderFrom.empty() ? runName : renderFrom}}},
      {"files", list}};
  writeFileAtomically(directory / kManifestName, doc.dump(2) + "\n");
  return entries;
}

ManifestRecord readManifest(const fs::path& directory) {
  const fs::path file = directory / kManifestName;
  // A manifest lists each file in about 100 bytes: far more files than a run writes.
  constexpr std::size_t kMaxManifestBytes = std::size_t{256} << 20;
  const std::string text = io::readFileNoFollow(file, kMaxManifestBytes);
  try {
    const nlohmann::json doc = nlohmann::json::parse(text);
    ManifestRecord manifest;
    manifest.inputs = readInputs(doc);
    if (const auto render = doc.find("render"); render != doc.end() && render->is_object()) {
      manifest.renderKey = render->value("key", "");
      manifest.renderFrom = render->value("from", "");
    }
    for (const auto& f : doc.at("files")) {
      manifest.files.push_back({f.at("path").get<std::string>(),
                                f.at("bytes").get<std::uintmax_t>(),
                                f.at("fnv1a64").get<std::string>()});
    }
    return manifest;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not a tofsim manifest: " + e.what());
  }
}

RunAssessment assessRun(const fs::path& directory, const RunContentKey& expected,
                        bool verifyChecksums) {
  std::error_code ec;
  if (!fs::exists(directory / kManifestName, ec)) {
    // A folder without a manifest is a run that started and did not finish.
    if (fs::is_directory(directory, ec)) return {RunState::Incomplete, "incomplete (no manifest)"};
    return {RunState::Missing, "missing"};
  }
  try {
    const ManifestRecord manifest = readManifest(directory);
    if (const std::string stale = staleReason(manifest, expected); !stale.empty()) {
      return {RunState::Stale, stale};
    }
    if (const std::string why = missingOutput(manifest, directory, verifyChecksums); !why.empty()) {
      return {RunState::Incomplete, "incomplete (" + why + ")"};
    }
  } catch (const std::exception& e) {
    return {RunState::Incomplete,
            std::string("incomplete (unreadable manifest: ") + e.what() + ")"};
  }
  return {RunState::Done, "done"};
}

}  // namespace tofsim::pipeline
