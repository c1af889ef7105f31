#pragma once
// `tofsim view OUTDIR [-o PAGE]`: the output folder as one HTML page
// (tofsim/viewer/ViewerPage.h).

#include <CLI/CLI.hpp>
#include <string>

namespace tofsim::cli {

struct ViewArgs {
  std::string folder, page;
};

CLI::App* addView(CLI::App& app, ViewArgs& args);
int runViewCommand(const ViewArgs& args);

}  // namespace tofsim::cli
