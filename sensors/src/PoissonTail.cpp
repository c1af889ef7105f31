#include "PoissonTail.h"

#include <cmath>
#include <limits>

namespace tofsim::sensors::detail {

namespace {

constexpr int kMaxTerms = 100000;
constexpr double kEps = 1e-16;

// ln of the common factor e^-x x^a / Gamma(a) of both expansions.
double logPrefactor(double a, double x) { return -x + a * std::log(x) - std::lgamma(a); }

// P(a, x) by its series, for x < a + 1 (converges in O(sqrt(a)) terms there).
double lowerSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int k = 1; k < kMaxTerms; ++k) {
    term *= x / (a + k);
    sum += term;
    if (term < sum * kEps) break;
  }
  return std::exp(logPrefactor(a, x)) * sum;
}

// ln Q(a, x) by Lentz's continued fraction, for x >= a + 1.
double logUpperFraction(double a, double x) {
  const double tiny = std::numeric_limits<double>::min() / kEps;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, f = d;
  for (int i = 1; i < kMaxTerms; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    f *= delta;
    if (std::fabs(delta - 1.0) < kEps) break;
  }
  return logPrefactor(a, x) + std::log(f);
}

}  // namespace

PoissonTail poissonTail(double n, double lambda) {
  PoissonTail t;
  if (!(n > 0.0)) {
    t.p = 1.0;
    t.logNotTail = -std::numeric_limits<double>::infinity();
    return t;
  }
  if (!(lambda > 0.0)) return t;  // p = 0, ln 1 = 0
  if (lambda < n + 1.0) {
    t.p = lowerSeries(n, lambda);
    t.logNotTail = std::log1p(-std::fmin(t.p, 1.0));
  } else {
    t.logNotTail = logUpperFraction(n, lambda);
    t.p = -std::expm1(t.logNotTail);
  }
  return t;
}

}  // namespace tofsim::sensors::detail
