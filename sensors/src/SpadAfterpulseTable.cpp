// A measured afterpulse delay density (issue 24, item 2): its bins and
// normalisation (Spad.h), its exact inverse for the event engine and its
// whole-bin masses for the fast path's release kernel (SpadDetector.h).

#include <algorithm>
#include <cmath>
#include <utility>

#include "SpadDetector.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

SpadAfterpulseTable afterpulseTable(std::string file, std::vector<double> delays_s,
                                    const std::vector<double>& values) {
  const std::size_t n = delays_s.size();
  TOFSIM_CHECK(n >= 2 && values.size() == n && delays_s[0] >= 0.0);
  SpadAfterpulseTable t;
  t.file = std::move(file);
  t.edges_s.resize(n + 1);
  t.edges_s[0] = std::max(0.0, delays_s[0] - 0.5 * (delays_s[1] - delays_s[0]));
  for (std::size_t k = 1; k < n; ++k) {
    TOFSIM_CHECK(delays_s[k] > delays_s[k - 1]);
    t.edges_s[k] = 0.5 * (delays_s[k - 1] + delays_s[k]);
  }
  t.edges_s[n] = delays_s[n - 1] + 0.5 * (delays_s[n - 1] - delays_s[n - 2]);
  double area = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    TOFSIM_CHECK(values[k] >= 0.0 && std::isfinite(values[k]));
    area += values[k] * (t.edges_s[k + 1] - t.edges_s[k]);
  }
  TOFSIM_CHECK(area > 0.0 && std::isfinite(area));
  t.density_per_s.resize(n);
  for (std::size_t k = 0; k < n; ++k) t.density_per_s[k] = values[k] / area;
  t.delays_s = std::move(delays_s);
  return t;
}

namespace detail {

void setAfterpulseTable(AfterpulseLaw& law, const SpadAfterpulseTable& table, double binWidth_s) {
  TOFSIM_CHECK(table.present() && binWidth_s > 0.0);
  law.table_edges_bins.clear();
  for (double e : table.edges_s) law.table_edges_bins.push_back(e / binWidth_s);
  law.table_cdf.assign(1, 0.0);
  for (std::size_t k = 0; k < table.density_per_s.size(); ++k) {
    law.table_cdf.push_back(law.table_cdf.back() +
                            table.density_per_s[k] * (table.edges_s[k + 1] - table.edges_s[k]));
  }
  law.table_cdf.back() = 1.0;  // normalised: rounding only
}

double tableDelay(const AfterpulseLaw& law, double u) {
  const std::vector<double>& F = law.table_cdf;
  const std::vector<double>& e = law.table_edges_bins;
  // The bin k with F_k <= u < F_(k+1): it has mass, so the division is safe.
  const auto it = std::upper_bound(F.begin() + 1, F.end(), u);
  const auto k = std::min<std::size_t>(static_cast<std::size_t>(it - F.begin()) - 1, F.size() - 2);
  const double mass = F[k + 1] - F[k];
  const double into = mass > 0.0 ? std::clamp((u - F[k]) / mass, 0.0, 1.0) : 0.0;
  return e[k] + into * (e[k + 1] - e[k]);
}

std::vector<double> tableBinMasses(const AfterpulseLaw& law) {
  const std::vector<double>& F = law.table_cdf;
  const std::vector<double>& e = law.table_edges_bins;
  // The distribution at x: linear between edges (a piecewise-constant density).
  const auto cdf = [&](double x) {
    if (!(x > e.front())) return 0.0;
    if (!(x < e.back())) return 1.0;
    const auto k =
        static_cast<std::size_t>(std::upper_bound(e.begin(), e.end(), x) - e.begin()) - 1;
    return F[k] + (F[k + 1] - F[k]) * (x - e[k]) / (e[k + 1] - e[k]);
  };
  const auto whole = static_cast<std::size_t>(std::ceil(e.back()));
  std::vector<double> masses(std::max<std::size_t>(whole, 1));
  double below = 0.0;
  for (std::size_t s = 0; s < masses.size(); ++s) {
    const double upTo = cdf(static_cast<double>(s + 1));
    masses[s] = upTo - below;
    below = upTo;
  }
  return masses;
}

}  // namespace detail
}  // namespace tofsim::sensors
