#include "tofsim/viewer/ViewerPage.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "Sections.h"
#include "ViewerBudget.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::viewer {

// viewer.html, embedded at build time (cmake/EmbedShaders.cmake).
const std::map<std::string, std::string, std::less<>>& embeddedPages();

namespace {

constexpr std::string_view kDataMarker = "@TOFSIM_VIEW_DATA@";

// The data as the text of a <script type="application/json">: "</" would end
// the element, so it is written "<\/" (the same string to JSON.parse).
std::string scriptSafeJson(const nlohmann::json& data) {
  std::string text = data.dump();
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

// A batch's or a capture sequence's folder holds one output per subfolder:
// the error names one to view instead.
std::string subfolderHint(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> outputs;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::filesystem::path p = entry.path();
    if (std::filesystem::is_regular_file(p / "transient.json", ec) ||
        std::filesystem::is_regular_file(p / "H.json", ec)) {
      outputs.push_back(p);
    }
  }
  if (outputs.empty()) return "";
  std::sort(outputs.begin(), outputs.end());
  return "; its subfolders are outputs (" + std::to_string(outputs.size()) +
         "): view one, e.g. tofsim view " + outputs.front().string();
}

nlohmann::json collectPage(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    throw InputError(FileLoc{folder.string()}, "",
                     "no such folder (tofsim view takes the "
                     "folder a render wrote, e.g. out/cornell_box)");
  }
  nlohmann::json page = {{"folder", std::filesystem::absolute(folder).lexically_normal().string()},
                         {"tofsim_version", pipeline::kVersion},
                         {"notes", nlohmann::json::array()},
                         {"lidars", nlohmann::json::array()}};
  if (!addCameraVolume(folder, page) && !addNlosVolume(folder, page) &&
      !addLidarVolume(folder, page)) {
    throw InputError(FileLoc{folder.string()}, "",
                     "not a tofsim output folder: it has none of transient.json (a camera "
                     "render), H.json (an NLOS capture) and lidar.json (a lidar)" +
                         subfolderHint(folder));
  }
  addMaps(folder, page);
  return page;
}

}  // namespace

ViewSummary writeViewerPage(const std::filesystem::path& folder, std::filesystem::path page) {
  if (page.empty()) page = folder / kDefaultPageName;
  const nlohmann::json data = collectPage(folder);
  std::string html = embeddedPages().at("viewer.html");
  const std::size_t at = html.find(kDataMarker);
  TOFSIM_CHECK_NE(at, std::string::npos);
  html.replace(at, kDataMarker.size(), scriptSafeJson(data));
  // The budgets bound the page (ViewerBudget.h); a page past this is a bug.
  TOFSIM_CHECK_LE(html.size(), kPageBytes);
  writeFileAtomically(page, html);
  return {page, html.size()};
}

}  // namespace tofsim::viewer
