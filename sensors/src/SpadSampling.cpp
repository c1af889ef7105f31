#include "SpadSampling.h"

#include <array>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {

// A binomial draw costs about as much as this many inverse-CDF draws
// (bench/spad_throughput): below that many expected detections per bin, the
// detections are drawn one by one.
constexpr double kDrawsPerBinomial = 4.0;

// Binomial(n, p) for n p < 10 and p <= 0.5 by inversion, as
// Rng::binomial's, with (1 - p)^n as exp(n log(1 - p)) from the caller's
// log(1 - p): a run of bins of one flux (the ambient floor) shares it.
// 1 / x for the first steps of the inversion (a division per step is its
// latency otherwise).
constexpr int kReciprocals = 64;
const std::array<double, kReciprocals>& reciprocals() {
  static const std::array<double, kReciprocals> table = [] {
    std::array<double, kReciprocals> t{};
    for (int x = 1; x < kReciprocals; ++x) t[x] = 1.0 / x;
    return t;
  }();
  return table;
}

uint64_t binomialByInversion(uint64_t n, double p, double log1mp, Rng& rng) {
  const std::array<double, kReciprocals>& inv = reciprocals();
  const double s = p / (1.0 - p);
  const double a = (static_cast<double>(n) + 1.0) * s;
  double r = std::exp(static_cast<double>(n) * log1mp);
  double u = rng.uniform();
  uint64_t x = 0;
  while (u > r && x < n) {
    u -= r;
    ++x;
    r *= (x < kReciprocals ? a * inv[x] : a / static_cast<double>(x)) - s;
    if (r <= 0.0) break;
  }
  return x;
}

// Runs of bins of one flux (the ambient floor) shorter than this take the
// generic draws: a FallingBinomial's tables cost about this many draws.
constexpr std::size_t kMinTableRun = 32;

// Binomial(n, q) by inversion below this mean, BTRS (Rng::binomial) above.
constexpr double kMaxInversionMean = 10.0;

void sequentialBinomials(const std::vector<double>& flux, uint64_t cycles, Rng& rng,
                         FallingBinomial& falling, std::vector<double>& h) {
  uint64_t remaining = cycles;
  double q = 0.0, log1mq = 0.0;
  bool tabled = false;
  for (std::size_t i = 0, runEnd = 0; i < flux.size() && remaining > 0; ++i) {
    if (i == runEnd) {  // a new run of bins [i, runEnd) of one flux
      while (runEnd < flux.size() && flux[runEnd] == flux[i]) ++runEnd;
      q = -std::expm1(-flux[i]);
      log1mq = -flux[i];  // log(1 - q) exactly
      tabled = runEnd - i >= kMinTableRun && FallingBinomial::suits(remaining, q);
      if (tabled) falling.reset(q);
    }
    uint64_t n = 0;
    if (tabled) {
      n = falling.draw(remaining, rng);
    } else if (q <= 0.5 && static_cast<double>(remaining) * q < kMaxInversionMean) {
      n = binomialByInversion(remaining, q, log1mq, rng);
    } else {
      n = rng.binomial(remaining, q);
    }
    h[i] = static_cast<double>(n);
    remaining -= n;
  }
}

// Each detection's bin from the CDF given a detection, cdf.back() == 1.
void inverseCdfDraws(uint64_t detections, Rng& rng, FirstPhotonScratch& s, std::vector<double>& h) {
  const auto K = s.cdf.size();
  // guide[j]: the first bin whose CDF exceeds j / K (Chen and Asau 1974).
  s.guide.resize(K);
  std::size_t i = 0;
  for (std::size_t j = 0; j < K; ++j) {
    const double u = static_cast<double>(j) / static_cast<double>(K);
    while (s.cdf[i] <= u) ++i;
    s.guide[j] = static_cast<int32_t>(i);
  }
  for (uint64_t d = 0; d < detections; ++d) {
    const double u = rng.uniform();  // [0, 1): stops at the last bin, whose CDF is 1
    std::size_t bin = static_cast<std::size_t>(s.guide[static_cast<std::size_t>(u * K)]);
    while (s.cdf[bin] <= u) ++bin;
    h[bin] += 1.0;
  }
}

}  // namespace

void firstPhotonHistogram(const std::vector<double>& flux, uint64_t cycles, Rng& rng,
                          FirstPhotonScratch& s, std::vector<double>& h) {
  const std::size_t K = flux.size();
  h.assign(K, 0.0);
  if (K == 0) return;
  double total = 0.0;
  for (const double f : flux) total += f;
  const double detect = -std::expm1(-total);  // P(any detection in a cycle)
  TOFSIM_CHECK(detect >= 0.0 && detect <= 1.0);
  if (!(detect > 0.0)) return;
  if (static_cast<double>(cycles) * detect > kDrawsPerBinomial * static_cast<double>(K)) {
    sequentialBinomials(flux, cycles, rng, s.falling, h);
    return;
  }
  // Survival: no detection up to the end of bin i with probability
  // exp(-F_{i+1}) (F the cumulative flux), a product of per-bin factors that
  // a run of bins of one flux shares; P(first detection by bin i) = 1 - that.
  s.cdf.resize(K);
  double survive = 1.0, lastFlux = -1.0, factor = 1.0;
  for (std::size_t i = 0; i < K; ++i) {
    if (flux[i] != lastFlux) {
      lastFlux = flux[i];
      factor = std::exp(-flux[i]);
    }
    survive *= factor;
    s.cdf[i] = 1.0 - survive;
  }
  const double last = s.cdf[K - 1];
  for (double& c : s.cdf) c /= last;  // the last is last / last == 1 exactly
  inverseCdfDraws(rng.binomial(cycles, detect), rng, s, h);
}

}  // namespace tofsim::sensors::detail
