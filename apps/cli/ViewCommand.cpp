#include "ViewCommand.h"

#include <cstdio>

#include "tofsim/viewer/ViewerPage.h"

namespace tofsim::cli {

CLI::App* addView(CLI::App& app, ViewArgs& args) {
  CLI::App* view = app.add_subcommand(
      "view",
      "Write an output folder's steady image, transient, histograms and sensor maps as "
      "one self-contained HTML page (OUTDIR/view.html)");
  view->add_option("folder", args.folder, "Output folder of a render (camera or NLOS)")->required();
  // -o "" would silently mean the default: a usage error, as for render's -o.
  view->add_option("-o,--output", args.page, "The page's path (default: OUTDIR/view.html)")
      ->check(CLI::Validator(
          [](const std::string& s) { return s.empty() ? "must not be empty" : std::string(); }, "",
          "NOT_EMPTY"));
  return view;
}

int runViewCommand(const ViewArgs& args) {
  const viewer::ViewSummary summary = viewer::writeViewerPage(args.folder, args.page);
  std::fprintf(stderr, "view: wrote %s (%.1f MiB)\n", summary.page.string().c_str(),
               static_cast<double>(summary.bytes) / (1 << 20));
  return 0;
}

}  // namespace tofsim::cli
