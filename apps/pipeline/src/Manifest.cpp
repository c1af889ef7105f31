#include "tofsim/pipeline/Manifest.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Hash.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

std::vector<ManifestEntry> writeManifest(const fs::path& directory, const std::string& runName) {
  std::vector<ManifestEntry> entries;
  for (const auto& e : fs::recursive_directory_iterator(directory)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), directory).generic_string();
    if (rel == kManifestName || rel == kRunLogName) continue;
    entries.push_back({rel, e.file_size(), hex64(fnv1a64File(e.path()))});
  }
  // Directory iteration order is unspecified; sorted, the manifest of the
  // same outputs is the same bytes.
  std::sort(entries.begin(), entries.end(),
            [](const ManifestEntry& a, const ManifestEntry& b) { return a.path < b.path; });
  nlohmann::json files = nlohmann::json::array();
  for (const ManifestEntry& m : entries) {
    files.push_back({{"path", m.path}, {"bytes", m.bytes}, {"fnv1a64", m.fnv1a64}});
  }
  const nlohmann::json doc = {{"run", runName}, {"hash", "fnv1a64"}, {"files", files}};
  writeFileAtomically(directory / kManifestName, doc.dump(2) + "\n");
  return entries;
}

bool runIsComplete(const fs::path& directory, bool verifyChecksums, std::string* why) {
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  const fs::path manifest = directory / kManifestName;
  std::ifstream in(manifest);
  if (!in) return fail("no manifest");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
    for (const auto& f : doc.at("files")) {
      const fs::path file = directory / f.at("path").get<std::string>();
      std::error_code ec;
      const std::uintmax_t size = fs::file_size(file, ec);
      if (ec) return fail("missing " + f.at("path").get<std::string>());
      if (size != f.at("bytes").get<std::uintmax_t>()) {
        return fail("size changed: " + f.at("path").get<std::string>());
      }
      if (verifyChecksums && hex64(fnv1a64File(file)) != f.at("fnv1a64").get<std::string>()) {
        return fail("checksum changed: " + f.at("path").get<std::string>());
      }
    }
  } catch (const std::exception& e) {
    return fail(std::string("unreadable manifest: ") + e.what());
  }
  return true;
}

}  // namespace tofsim::pipeline
