#include "tofsim/pipeline/CompareRun.h"

#include <cstdio>
#include <optional>

#include "tofsim/imaging/LinePlot.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/io/Exr.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/FolderPath.h"

namespace tofsim::pipeline {

namespace {

// The components a render may write (output.components; at most
// render.indirect.bounces = 8 bounces), in the order they are reported.
std::vector<std::string> componentNames() {
  std::vector<std::string> names = {"direct", "indirect"};
  for (int k = 1; k <= 8; ++k) names.push_back("bounce" + std::to_string(k));
  return names;
}

std::vector<ComponentComparison> compareComponents(const std::filesystem::path& a,
                                                   const std::filesystem::path& b) {
  std::vector<ComponentComparison> out;
  for (const std::string& name : componentNames()) {
    const std::optional<TransientVolume> inA = loadSavedComponent(a, name);
    if (!inA) continue;
    const std::optional<TransientVolume> inB = loadSavedComponent(b, name);
    if (!inB) continue;
    out.push_back({name, compare::compareVolumes(*inA, *inB)});
  }
  return out;
}

std::string componentsCsv(const std::vector<ComponentComparison>& components) {
  std::string csv = "component,steady_relative_l1,steady_rmse,transient_relative_l1\n";
  for (const ComponentComparison& c : components) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.9g,%.9g,%.9g\n", c.name.c_str(),
                  c.comparison.steadyRelativeL1, c.comparison.steadyRmse,
                  c.comparison.transientRelativeL1);
    csv += line;
  }
  return csv;
}

}  // namespace

std::string componentsTable(const std::vector<ComponentComparison>& components) {
  if (components.empty()) return "";
  std::string text = "components (in both A and B): steady rel. L1, transient rel. L1\n";
  for (const ComponentComparison& c : components) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-10s %.6g  %.6g\n", c.name.c_str(),
                  c.comparison.steadyRelativeL1, c.comparison.transientRelativeL1);
    text += line;
  }
  return text;
}

CompareSummary runCompare(const std::filesystem::path& a, const std::filesystem::path& b,
                          const std::filesystem::path& outputDirectory) {
  // Before the volumes are read: a file in the folder's place is the option's
  // error, not a bare "cannot create directories" after the work.
  const std::string folderProblem = folderPathProblem(outputDirectory);
  if (!folderProblem.empty()) {
    throw InputError(FileLoc{outputDirectory.string()}, "-o/--output", folderProblem);
  }
  const SavedVolume volumeA = loadSavedVolume(a);
  const SavedVolume volumeB = loadSavedVolume(b);
  CompareSummary summary;
  summary.comparison = compare::compareVolumes(volumeA.volume, volumeB.volume);
  const compare::VolumeComparison& c = summary.comparison;
  // Every volume read (and checked) before the first file is written.
  summary.components = compareComponents(a, b);

  std::error_code ec;
  std::filesystem::create_directories(outputDirectory, ec);
  if (ec) {
    throw InputError(FileLoc{outputDirectory.string()}, "-o/--output",
                     "cannot create the folder: " + ec.message());
  }
  writeFileAtomically(outputDirectory / "compare_energy.csv", compare::energyCurveCsv(c));
  summary.files.push_back("compare_energy.csv");

  imaging::LinePlot plot;
  plot.series = {std::vector<float>(c.energyA.begin(), c.energyA.end()),
                 std::vector<float>(c.energyB.begin(), c.energyB.end())};
  plot.labels = {"A: " + a.filename().string(), "B: " + b.filename().string()};
  plot.x0 = c.axis.start_s * 1e9;
  plot.dx = c.axis.bin_width_s * 1e9;
  plot.xUnit = "ns";
  plot.yLabel = "radiance summed over the image";
  plot.title = "energy over time (A under test, B reference)";
  imaging::writeLinePlotPng(outputDirectory / "compare_energy.png", plot);
  summary.files.push_back("compare_energy.png");

  io::writeExr(outputDirectory / "compare_arrival.exr", c.earliestArrivalDifference_s, {"Y"});
  Image arrival_ps = c.earliestArrivalDifference_s;
  for (float& v : arrival_ps.data) v *= 1e12f;
  imaging::ColorScale scale;
  scale.diverging = true;  // a signed difference: 0 = the same arrival
  imaging::writeColormappedPng(outputDirectory / "compare_arrival.png", arrival_ps,
                               "earliest arrival A - B [ps]", scale);
  summary.files.push_back("compare_arrival.exr");
  summary.files.push_back("compare_arrival.png");
  if (!summary.components.empty()) {
    writeFileAtomically(outputDirectory / "compare_components.csv",
                        componentsCsv(summary.components));
    summary.files.push_back("compare_components.csv");
  }
  return summary;
}

}  // namespace tofsim::pipeline
