// Binomial draws of Rng: inversion for small means, BTRS above.
#include <array>
#include <cmath>
#include <string>

#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {

// BTRS's constants hold for n p >= 10 (Hormann 1993); below, inversion takes
// about n p + 1 steps, so it is as cheap.
constexpr double kMinBtrsMean = 10.0;

// log(k!) - [(k + 1/2) log(k + 1) - (k + 1) + log(2 pi) / 2]: the error of
// Stirling's formula at k + 1, from a table below 10 and from three terms of
// its series above (error below 1e-11 there).
double stirlingTail(double k) {
  static constexpr std::array<double, 10> kTable = {
      0.0810614667953272,  0.0413406959554092, 0.0276779256849983, 0.02079067210376509,
      0.0166446911898211,  0.0138761288230707, 0.0118967099458917, 0.0104112652619720,
      0.00925546218271273, 0.00833056343336287};
  if (k <= 9.0) return kTable[static_cast<std::size_t>(k)];
  const double kp1sq = (k + 1.0) * (k + 1.0);
  return (1.0 / 12.0 - (1.0 / 360.0 - 1.0 / 1260.0 / kp1sq) / kp1sq) / (k + 1.0);
}

}  // namespace

uint64_t Rng::binomialInversion(uint64_t n, double p) {
  // p <= 0.5 and n p small, so q^n does not underflow.
  const double q = 1.0 - p;
  const double s = p / q;
  const double a = (static_cast<double>(n) + 1.0) * s;
  double r = std::pow(q, static_cast<double>(n));
  double u = uniform();
  uint64_t x = 0;
  while (u > r && x < n) {
    u -= r;
    ++x;
    r *= a / static_cast<double>(x) - s;
    if (r <= 0.0) break;
  }
  return x;
}

// BTRS: transformed rejection with squeeze (Hormann 1993, "The generation of
// binomial random variates", J. Stat. Comput. Simul. 46), p <= 0.5 and
// n p >= 10. The hat is a transformed uniform; most draws end in the box
// (about 86 % of v_r), the others compare with log f(k) / f(m), m the mode,
// through Stirling's formula (exact up to its tail's 1e-11). Two uniforms
// per try, at most a few logarithms; constant expected time in n.
uint64_t Rng::binomialBtrs(uint64_t n, double p) {
  const double count = static_cast<double>(n);
  const double spq = std::sqrt(count * p * (1.0 - p));
  const double b = 1.15 + 2.53 * spq;
  const double a = -0.0873 + 0.0248 * b + 0.01 * p;
  const double c = count * p + 0.5;
  const double vr = 0.92 - 4.2 / b;
  const double r = p / (1.0 - p);
  const double alpha = (2.83 + 5.1 / b) * spq;
  const double m = std::floor((count + 1.0) * p);
  for (;;) {
    const double u = uniform() - 0.5;
    double v = uniform();
    const double us = 0.5 - std::fabs(u);
    const double k = std::floor((2.0 * a / us + b) * u + c);
    if (!(k >= 0.0 && k <= count)) continue;  // also us == 0 (k = -inf or NaN)
    if (us >= 0.07 && v <= vr) return static_cast<uint64_t>(k);
    v = std::log(v * alpha / (a / (us * us) + b));
    const double bound = (m + 0.5) * std::log((m + 1.0) / (r * (count - m + 1.0))) +
                         (count + 1.0) * std::log((count - m + 1.0) / (count - k + 1.0)) +
                         (k + 0.5) * std::log(r * (count - k + 1.0) / (k + 1.0)) + stirlingTail(m) +
                         stirlingTail(count - m) - stirlingTail(k) - stirlingTail(count - k);
    if (v <= bound) return static_cast<uint64_t>(k);
  }
}

uint64_t Rng::binomial(uint64_t n, double p) {
  TOFSIM_CHECK_MSG(p >= 0.0 && p <= 1.0, "binomial p " + std::to_string(p));
  if (n == 0 || p <= 0.0) return 0;
  if (p >= 1.0) return n;
  const bool flip = p > 0.5;  // Binomial(n, p) = n - Binomial(n, 1 - p)
  const double pp = flip ? 1.0 - p : p;
  const uint64_t x =
      static_cast<double>(n) * pp < kMinBtrsMean ? binomialInversion(n, pp) : binomialBtrs(n, pp);
  return flip ? n - x : x;
}

}  // namespace tofsim::sensors
