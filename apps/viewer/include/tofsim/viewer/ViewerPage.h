#pragma once
// `tofsim view OUTDIR`: one self-contained HTML page of a render's outputs
// (README.md, "Looking at a render"): the steady image, a time slider through
// the transient, a clicked pixel's histogram (time in ns and metres of path),
// every sensor map with its colour bar; for an NLOS capture H's time slices.
// Scripts and data are inline (no network); what would not fit the page's
// budget (ViewerBudget.h: under 24 MiB) is downsampled, and the page says how.

#include <cstddef>
#include <filesystem>

namespace tofsim::viewer {

struct ViewSummary {
  std::filesystem::path page;
  std::size_t bytes = 0;
};

/// Reads the output folder `folder` (a camera render: transient.json with
/// transient.npy or capture.h5; an NLOS capture: H.json with H.npy) and
/// writes the page to `page` atomically (default folder/view.html when
/// empty). Throws InputError naming the folder or the file when the folder is
/// not a tofsim output or a file in it cannot be read; nothing is written then.
ViewSummary writeViewerPage(const std::filesystem::path& folder, std::filesystem::path page = {});

/// The page's default name in the folder.
inline constexpr const char* kDefaultPageName = "view.html";

}  // namespace tofsim::viewer
