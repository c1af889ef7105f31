#include "tofsim/compare/VolumeComparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "tofsim/util/Error.h"

namespace tofsim::compare {

namespace {

bool nearlyEqual(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

void requireSameShape(const TransientVolume& a, const TransientVolume& b) {
  const auto shape = [](const TransientVolume& v) {
    return std::to_string(v.height()) + "x" + std::to_string(v.width()) + "x" +
           std::to_string(v.bins()) + "x" + std::to_string(v.channels());
  };
  if (a.width() != b.width() || a.height() != b.height() || a.bins() != b.bins() ||
      a.channels() != b.channels()) {
    throw InputError("cannot compare volumes of shapes (H, W, T, C) " + shape(a) + " and " +
                     shape(b));
  }
  if (!nearlyEqual(a.axis().start_s, b.axis().start_s) ||
      !nearlyEqual(a.axis().bin_width_s, b.axis().bin_width_s)) {
    throw InputError("cannot compare volumes with different time axes (start " +
                     std::to_string(a.axis().start_s) + " s vs " +
                     std::to_string(b.axis().start_s) + " s, bin width " +
                     std::to_string(a.axis().bin_width_s) + " s vs " +
                     std::to_string(b.axis().bin_width_s) + " s)");
  }
}

double relative(double difference, double reference) {
  if (reference > 0.0) return difference / reference;
  return difference == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

}  // namespace

int32_t earliestArrivalBin(const TransientVolume& v, int32_t y, int32_t x, double threshold) {
  double peak = 0.0;
  for (int32_t t = 0; t < v.bins(); ++t) {
    double e = 0.0;
    for (int32_t c = 0; c < v.channels(); ++c) e += v.at(y, x, t, c);
    peak = std::max(peak, e);
  }
  if (!(peak > 0.0)) return -1;
  for (int32_t t = 0; t < v.bins(); ++t) {
    double e = 0.0;
    for (int32_t c = 0; c < v.channels(); ++c) e += v.at(y, x, t, c);
    if (e >= threshold * peak) return t;
  }
  return -1;  // unreachable: the peak bin itself qualifies
}

VolumeComparison compareVolumes(const TransientVolume& a, const TransientVolume& b,
                                const CompareOptions& options) {
  requireSameShape(a, b);
  VolumeComparison r;
  r.axis = b.axis();
  r.energyA.assign(static_cast<std::size_t>(b.bins()), 0.0);
  r.energyB.assign(static_cast<std::size_t>(b.bins()), 0.0);
  r.earliestArrivalDifference_s = Image(b.width(), b.height(), 1);

  double steadyDiff = 0.0, steadyRef = 0.0, steadySquared = 0.0;
  double transientDiff = 0.0, transientRef = 0.0;
  double arrivalSum = 0.0;
  for (int32_t y = 0; y < b.height(); ++y) {
    for (int32_t x = 0; x < b.width(); ++x) {
      for (int32_t c = 0; c < b.channels(); ++c) {
        double sa = 0.0, sb = 0.0;
        for (int32_t t = 0; t < b.bins(); ++t) {
          const double va = a.at(y, x, t, c), vb = b.at(y, x, t, c);
          sa += va;
          sb += vb;
          transientDiff += std::abs(va - vb);
          transientRef += std::abs(vb);
          r.energyA[static_cast<std::size_t>(t)] += va;
          r.energyB[static_cast<std::size_t>(t)] += vb;
        }
        steadyDiff += std::abs(sa - sb);
        steadyRef += std::abs(sb);
        steadySquared += (sa - sb) * (sa - sb);
      }
      const int32_t ta = earliestArrivalBin(a, y, x, options.arrival_threshold);
      const int32_t tb = earliestArrivalBin(b, y, x, options.arrival_threshold);
      if (ta >= 0 && tb >= 0) {
        const double d = a.axis().binStart_s(ta) - b.axis().binStart_s(tb);
        r.earliestArrivalDifference_s.at(y, x, 0) = static_cast<float>(d);
        arrivalSum += std::abs(d);
        r.maxEarliestArrivalDifference_s = std::max(r.maxEarliestArrivalDifference_s, std::abs(d));
        ++r.arrivalPixelsCompared;
      } else if (ta >= 0 || tb >= 0) {
        ++r.arrivalPixelsUnmatched;
      }
    }
  }
  const double values = static_cast<double>(b.width()) * b.height() * b.channels();
  r.steadyRelativeL1 = relative(steadyDiff, steadyRef);
  r.steadyRmse = std::sqrt(steadySquared / values);
  r.transientRelativeL1 = relative(transientDiff, transientRef);
  if (r.arrivalPixelsCompared > 0) {
    r.meanEarliestArrivalDifference_s = arrivalSum / static_cast<double>(r.arrivalPixelsCompared);
  }
  return r;
}

std::string energyCurveCsv(const VolumeComparison& comparison) {
  std::string csv = "bin,time_s,energy_a,energy_b\n";
  char line[128];
  for (std::size_t t = 0; t < comparison.energyB.size(); ++t) {
    std::snprintf(line, sizeof(line), "%zu,%.17g,%.17g,%.17g\n", t,
                  comparison.axis.binCenter_s(static_cast<int32_t>(t)), comparison.energyA[t],
                  comparison.energyB[t]);
    csv += line;
  }
  return csv;
}

std::string summaryTable(const VolumeComparison& c) {
  char text[768];
  std::snprintf(text, sizeof(text),
                "steady relative L1          %.6g\n"
                "steady RMSE                 %.6g W/(m^2 sr)\n"
                "transient relative L1       %.6g\n"
                "earliest arrival |A-B| mean %.6g s\n"
                "earliest arrival |A-B| max  %.6g s\n"
                "arrival pixels compared     %zu (%zu with an arrival in one volume only)\n",
                c.steadyRelativeL1, c.steadyRmse, c.transientRelativeL1,
                c.meanEarliestArrivalDifference_s, c.maxEarliestArrivalDifference_s,
                c.arrivalPixelsCompared, c.arrivalPixelsUnmatched);
  return text;
}

}  // namespace tofsim::compare
