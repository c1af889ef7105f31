#pragma once
// Reproducible random numbers for the sensor models: the samplers of the
// laws they draw (normal, Poisson, binomial, gamma, beta), written on tofsim's
// one generator (PCG32 seeded through SplitMix64, util/Random.h), so that the
// same seed gives the same bytes on every platform's standard library. Each
// pixel gets its own stream derived from (seed, stream id), so results do not
// depend on iteration order. The generator's step and the uniform are inline:
// the SPAD draws one per detection or bin.

#include <cstdint>

#include "tofsim/util/Random.h"

namespace tofsim::sensors {

class Rng {
 public:
  Rng(uint64_t seed, uint64_t stream) : engine_(Pcg32::forStream(seed, stream)) {}

  uint32_t nextU32() { return engine_.nextUint(); }
  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return engine_.nextDouble(); }
  /// uniform() when it is >= p, else -1: the same law, but the low 26 bits
  /// are drawn only when the high 27 do not decide (a generator step saved
  /// where u < p is likely).
  double uniformUnless(double p) {
    const uint64_t hi = nextU32() >> 5;
    const double edge = p * 0x1.0p27;
    if (static_cast<double>(hi) + 1.0 <= edge) return -1.0;  // u < (hi + 1) 2^-27 <= p
    const double u = static_cast<double>((hi << 26) | (nextU32() >> 6)) * 0x1.0p-53;
    return u < p ? -1.0 : u;
  }
  /// Standard normal (Box-Muller, both values used).
  double normal();
  double normal(double mean, double sigma) { return mean + sigma * normal(); }
  /// Poisson with the given mean >= 0 (inversion below 12, PTRS above).
  uint64_t poisson(double mean);
  /// Binomial(n, p), exact: inversion for n min(p, 1 - p) < 10, else BTRS
  /// (Hormann 1993), constant expected time. Binomial.cpp.
  uint64_t binomial(uint64_t n, double p);
  /// Gamma(shape, 1), shape > 0 (Marsaglia-Tsang).
  double gamma(double shape);
  /// Beta(a, b) as G_a / (G_a + G_b).
  double beta(double a, double b);

 private:
  uint64_t binomialInversion(uint64_t n, double p);
  uint64_t binomialBtrs(uint64_t n, double p);

  Pcg32 engine_;
  double spare_ = 0.0;
  bool hasSpare_ = false;
};

/// Stream ids: a model tag in the high bits, the pixel index below.
inline uint64_t pixelStream(uint32_t tag, uint64_t pixelIndex) {
  return (static_cast<uint64_t>(tag) << 48) ^ pixelIndex;
}

}  // namespace tofsim::sensors
