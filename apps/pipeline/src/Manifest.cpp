#include "tofsim/pipeline/Manifest.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tofsim/util/AtomicFile.h"
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

std::string staleReason(const nlohmann::json& doc, const RunContentKey& expected) {
  const auto inputs = doc.find("inputs");
  if (inputs == doc.end() || !inputs->is_object()) return "stale (no inputs recorded)";
  const auto differs = [&](const char* key, const std::string& want) {
    const auto it = inputs->find(key);
    return it == inputs->end() || !it->is_string() || it->get<std::string>() != want;
  };
  if (differs("config", expected.config)) return "stale (config changed)";
  if (differs("scene", expected.scene)) return "stale (scene changed)";
  if (differs("version", expected.version)) return "stale (version changed)";
  return "";
}

// "" when every listed file is there with its size (and checksum).
std::string missingOutput(const nlohmann::json& doc, const fs::path& directory, bool verify) {
  for (const auto& f : doc.at("files")) {
    const std::string name = f.at("path").get<std::string>();
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(directory / name, ec);
    if (ec) return "missing " + name;
    if (size != f.at("bytes").get<std::uintmax_t>()) return "size changed: " + name;
    if (verify && hex64(fnv1a64File(directory / name)) != f.at("fnv1a64").get<std::string>()) {
      return "checksum changed: " + name;
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

RunAssessment assessRun(const fs::path& directory, const RunContentKey& expected,
                        bool verifyChecksums) {
  std::error_code ec;
  if (!fs::exists(directory / kManifestName, ec)) {
    // A folder without a manifest is a run that started and did not finish.
    if (fs::is_directory(directory, ec)) return {RunState::Incomplete, "incomplete (no manifest)"};
    return {RunState::Missing, "missing"};
  }
  try {
    std::ifstream in(directory / kManifestName);
    const nlohmann::json doc = nlohmann::json::parse(in);
    if (const std::string stale = staleReason(doc, expected); !stale.empty()) {
      return {RunState::Stale, stale};
    }
    if (const std::string why = missingOutput(doc, directory, verifyChecksums); !why.empty()) {
      return {RunState::Incomplete, "incomplete (" + why + ")"};
    }
  } catch (const std::exception& e) {
    return {RunState::Incomplete,
            std::string("incomplete (unreadable manifest: ") + e.what() + ")"};
  }
  return {RunState::Done, "done"};
}

}  // namespace tofsim::pipeline
