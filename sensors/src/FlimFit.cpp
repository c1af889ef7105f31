#include "FlimFit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
constexpr int kParams = 4;  // ln A, ln B, ln tau, s
using Vec = std::array<double, kParams>;
using Mat = std::array<Vec, kParams>;

constexpr int32_t kMaxIterations = 200;
constexpr double kStepTau = 1e-4;       // central difference in ln tau
constexpr double kConvergedNats = 1e-7;  // a step gaining less than this ends the fit
constexpr double kMinLnB = -40.0;        // B >= 4e-18 counts per bin: no background

// Solves m x = b over the `active` unknowns (the others 0) by Gaussian
// elimination with partial pivoting; false when singular.
bool solve(Mat m, Vec b, const std::array<bool, kParams>& active, Vec& x) {
  std::array<int, kParams> idx{};
  int n = 0;
  for (int i = 0; i < kParams; ++i) {
    if (active[i]) idx[n++] = i;
  }
  double a[kParams][kParams + 1];
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) a[r][c] = m[idx[r]][idx[c]];
    a[r][n] = b[idx[r]];
  }
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int r = c + 1; r < n; ++r) {
      if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
    }
    if (!(std::fabs(a[pivot][c]) > 0.0)) return false;
    for (int k = 0; k <= n; ++k) std::swap(a[c][k], a[pivot][k]);
    for (int r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k <= n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  x.fill(0.0);
  for (int r = n - 1; r >= 0; --r) {
    double v = a[r][n];
    for (int k = r + 1; k < n; ++k) v -= a[r][k] * x[idx[k]];
    x[idx[r]] = v / a[r][r];
  }
  for (double v : x) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}
}  // namespace

struct FlimFitter::Point {
  Vec v{};  // ln A, ln B, ln tau (bins), s (bins from the axis start)
  double L = -std::numeric_limits<double>::infinity();
};

FlimFitter::FlimFitter(const BinKernel& kernel, const TimeAxis& axis)
    : kernel_(kernel), axis_(axis) {
  TOFSIM_CHECK(!kernel_.weights.empty() && axis_.bins > 0 && axis_.bin_width_s > 0.0);
  double sum = 0.0, best = -1.0;
  for (std::size_t j = 0; j < kernel_.weights.size(); ++j) {
    const double w = kernel_.weights[j];
    sum += w;
    kernelMean_ += w * (kernel_.first + static_cast<double>(j));
    best = std::max(best, w);
  }
  kernelMean_ /= sum;
  std::size_t rise = 0;
  while (kernel_.weights[rise] < 0.5 * best) ++rise;
  kernelHalfRise_ = kernel_.first + static_cast<int32_t>(rise);
}

void FlimFitter::decay(double tau, double onset, std::vector<double>& z) const {
  const int32_t K = axis_.bins;
  z.assign(static_cast<std::size_t>(K), 0.0);
  const auto n0 = static_cast<int64_t>(std::floor(onset));
  const double delta = onset - static_cast<double>(n0);
  // e[n0] = e0, e[n0 + m] = e1 a^(m - 1) (m >= 1): the exact bin integrals.
  const double a = std::exp(-1.0 / tau);
  const double e0 = -std::expm1(-(1.0 - delta) / tau);
  const double e1 = std::exp(-(1.0 - delta) / tau) * -std::expm1(-1.0 / tau);
  const std::vector<double>& k = kernel_.weights;
  const auto L = static_cast<int64_t>(k.size());
  const int64_t base = n0 + kernel_.first;  // k's index of bin n is n - base
  const auto kAt = [&](int64_t j) { return j >= 0 && j < L ? k[static_cast<std::size_t>(j)] : 0.0; };
  // (k * e)[n] = e0 k[n - base] + e1 r[n], r[n] = a r[n - 1] + k[n - base - 1].
  double r = 0.0;
  for (int64_t n = std::min<int64_t>(0, base); n < K; ++n) {
    r = a * r + kAt(n - base - 1);
    if (n >= 0) z[static_cast<std::size_t>(n)] = e0 * kAt(n - base) + e1 * r;
  }
}

void FlimFitter::expected(double amplitude, double background, double lifetime_s, double onset_s,
                          std::vector<double>& mu) const {
  const double w = axis_.bin_width_s;
  decay(lifetime_s / w, (onset_s - axis_.start_s) / w, mu);
  for (double& m : mu) m = amplitude * m + background;
}

double FlimFitter::logLikelihood(const std::vector<double>& h, const Point& p, Scratch& s) const {
  decay(std::exp(p.v[2]), p.v[3], s.z);
  const double A = std::exp(p.v[0]), B = std::exp(p.v[1]);
  double L = 0.0;
  for (std::size_t n = 0; n < s.end; ++n) {
    const double mu = A * s.z[n] + B;
    L += (h[n] > 0.0 ? h[n] * std::log(mu) : 0.0) - mu;
  }
  return std::isfinite(L) ? L : -std::numeric_limits<double>::infinity();
}

// A start the scoring converges from: B half the lowest window's mean, s at
// the rising edge, tau from the centroid (e's mean is
// s + tau, the kernel adds its mean), A the counts above B.
FlimFitter::Point FlimFitter::start(const std::vector<double>& h, Scratch& s) const {
  const auto K = static_cast<int32_t>(h.size());
  const int32_t window = std::max(4, K / 32);
  double lowest = std::numeric_limits<double>::infinity();
  for (int32_t b = 0; b + window <= K; b += std::max(1, window / 2)) {
    double sum = 0.0;
    for (int32_t i = b; i < b + window; ++i) sum += h[static_cast<std::size_t>(i)];
    lowest = std::min(lowest, sum / window);
  }
  if (!std::isfinite(lowest)) lowest = 0.0;
  const double B0 = 0.5 * lowest;
  // The onset from the rising edge: the first bin at half the peak above B0
  // (a late start would leave counts before it that no gradient sees: the
  // model is flat in s there), less the kernel's own rise to its half.
  const double peak = *std::max_element(h.begin(), h.end());
  int32_t rise = 0;
  while (rise + 1 < K && h[static_cast<std::size_t>(rise)] - B0 < 0.5 * (peak - B0)) ++rise;
  const double s0 = rise - kernelHalfRise_;
  double above = 0.0, moment = 0.0;
  for (int32_t n = 0; n < K; ++n) {
    const double v = std::max(0.0, h[static_cast<std::size_t>(n)] - B0);
    above += v;
    moment += v * (n + 0.5);
  }
  const double tau0 = std::clamp(moment / std::max(above, 1e-300) - s0 - kernelMean_, 0.5,
                                 0.5 * static_cast<double>(K));
  decay(tau0, s0, s.z);
  double zSum = 0.0;
  for (double v : s.z) zSum += v;
  Point p;
  p.v = {std::log(std::max(above, 1.0) / std::max(zSum, 1e-3)),
         std::max(kMinLnB, std::log(std::max(B0, 1e-300))), std::log(tau0), s0};
  return p;
}

struct FlimFitter::Information {
  Mat I{};  ///< Fisher information of (ln A, ln B, ln tau, s)
  Vec g{};  ///< the score, d(log-likelihood)
  std::array<bool, kParams> active{};
};

// I = sum_n J J^T / mu_n and g = sum_n J (h_n / mu_n - 1), J = d mu_n /
// d(ln A, ln B, ln tau, s): d/ds in closed form ((z - k) / tau: a shift of
// the decay moves its start's unit impulse), d/d ln tau by a central
// difference.
void FlimFitter::information(const std::vector<double>& h, const Point& q, Scratch& s,
                             Information& out) const {
  const double A = std::exp(q.v[0]), B = std::exp(q.v[1]), tau = std::exp(q.v[2]);
  decay(tau * std::exp(kStepTau), q.v[3], s.zUp);
  decay(tau * std::exp(-kStepTau), q.v[3], s.zDown);
  decay(tau, q.v[3], s.z);
  const int64_t base = static_cast<int64_t>(std::floor(q.v[3])) + kernel_.first;
  const auto L = static_cast<int64_t>(kernel_.weights.size());
  for (auto& row : out.I) row.fill(0.0);
  out.g.fill(0.0);
  for (std::size_t i = 0; i < s.end; ++i) {
    const int64_t j = static_cast<int64_t>(i) - base;
    const double kj = j >= 0 && j < L ? kernel_.weights[static_cast<std::size_t>(j)] : 0.0;
    const Vec J = {A * s.z[i], B, A * (s.zUp[i] - s.zDown[i]) / (2.0 * kStepTau),
                   A * (s.z[i] - kj) / tau};
    const double mu = A * s.z[i] + B;
    const double r = h[i] / mu - 1.0;
    for (int a = 0; a < kParams; ++a) {
      out.g[a] += J[a] * r;
      for (int b = 0; b <= a; ++b) out.I[a][b] += J[a] * J[b] / mu;
    }
  }
  double largest = 0.0;
  for (int a = 0; a < kParams; ++a) {
    for (int b = 0; b < a; ++b) out.I[b][a] = out.I[a][b];
    largest = std::max(largest, out.I[a][a]);
  }
  // A background at its floor carries no information: held there.
  for (int a = 0; a < kParams; ++a) out.active[a] = out.I[a][a] > 1e-14 * largest;
}

FlimFit FlimFitter::fit(const std::vector<double>& h, Scratch& s, int32_t endBin) const {
  const int32_t K = axis_.bins;
  TOFSIM_CHECK(static_cast<int32_t>(h.size()) == K);
  s.end = static_cast<std::size_t>(std::clamp(endBin, 1, K));
  FlimFit out;
  double total = 0.0;
  for (double v : h) total += v;
  if (!(total > 0.0)) return out;
  const double sLo = -static_cast<double>(kernel_.weights.size()) - std::abs(kernel_.first) - 2.0;
  const double lnTauLo = std::log(0.05), lnTauHi = std::log(100.0 * K);
  const Vec lo = {-50.0, kMinLnB, lnTauLo, sLo};
  const Vec hi = {std::log(total) + 20.0, std::log(total), lnTauHi, static_cast<double>(K)};
  const Vec maxStep = {2.0, 5.0, 1.0, std::max(2.0, K / 8.0)};
  Point p = start(h, s);
  for (int i = 0; i < kParams; ++i) p.v[i] = std::clamp(p.v[i], lo[i], hi[i]);
  p.L = logLikelihood(h, p, s);

  Information info;
  double lambda = 1e-3;
  for (out.iterations = 0; out.iterations < kMaxIterations; ++out.iterations) {
    information(h, p, s, info);
    const Mat& I = info.I;
    bool accepted = false;
    double gain = 0.0;
    for (int tries = 0; tries < 40 && !accepted; ++tries) {
      Mat M = I;
      for (int a = 0; a < kParams; ++a) M[a][a] *= 1.0 + lambda;
      Vec step{};
      if (solve(M, info.g, info.active, step)) {
        Point q = p;
        for (int a = 0; a < kParams; ++a) {
          q.v[a] = std::clamp(p.v[a] + std::clamp(step[a], -maxStep[a], maxStep[a]), lo[a], hi[a]);
        }
        q.L = logLikelihood(h, q, s);
        if (q.L >= p.L) {
          gain = q.L - p.L;
          p = q;
          accepted = true;
          lambda = std::max(lambda * 0.3, 1e-12);
          break;
        }
      }
      lambda *= 10.0;
    }
    if (!accepted || gain < kConvergedNats) {
      out.converged = true;
      break;
    }
  }
  // At a bound the optimum is outside what the model describes.
  if (p.v[2] <= lnTauLo + 1e-9 || p.v[2] >= lnTauHi - 1e-9 || p.v[3] <= sLo || p.v[3] >= K) {
    out.converged = false;
  }
  if (!out.converged) return out;
  information(h, p, s, info);
  const double tau = std::exp(p.v[2]);
  const double w = axis_.bin_width_s;
  out.lifetime_s = tau * w;
  out.onset_s = axis_.start_s + p.v[3] * w;
  out.amplitude = std::exp(p.v[0]);
  out.background = std::exp(p.v[1]) > std::exp(kMinLnB + 1.0) ? std::exp(p.v[1]) : 0.0;
  // Cramer-Rao: var(ln tau) = (I^-1)_(ln tau, ln tau).
  Vec unitTau{0.0, 0.0, 1.0, 0.0}, column{};
  if (info.active[2] && solve(info.I, unitTau, info.active, column) && column[2] > 0.0) {
    out.lifetime_sigma_s = out.lifetime_s * std::sqrt(column[2]);
  }
  return out;
}

}  // namespace tofsim::sensors::detail
