#include "tofsim/pipeline/CompareRun.h"

#include "tofsim/imaging/LinePlot.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/io/Exr.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/util/AtomicFile.h"

namespace tofsim::pipeline {

CompareSummary runCompare(const std::filesystem::path& a, const std::filesystem::path& b,
                          const std::filesystem::path& outputDirectory) {
  const SavedVolume volumeA = loadSavedVolume(a);
  const SavedVolume volumeB = loadSavedVolume(b);
  CompareSummary summary;
  summary.comparison = compare::compareVolumes(volumeA.volume, volumeB.volume);
  const compare::VolumeComparison& c = summary.comparison;

  std::filesystem::create_directories(outputDirectory);
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
  return summary;
}

}  // namespace tofsim::pipeline
