#pragma once
// Deterministic random numbers: tofsim's one generator, for the renderers
// and the sensor models (sensors/Random.h draws its laws from it).
//
// Every independent unit of work (a pixel, a VPL, ...) gets its own generator
// derived from (run seed, unit index) by SplitMix64, so results depend only on
// the seed and the unit, never on which thread ran it or in what order.
// The generator is PCG32 (O'Neill 2014, pcg32_random_r): 64-bit state, 32-bit
// output, and a stream selector that decorrelates units with nearby seeds.

#include <cstdint>

namespace tofsim {

/// One step of SplitMix64 (Steele, Lea, Flood 2014): a strong 64-bit mixer,
/// used to turn (seed, index) into well-spread PCG32 state and stream.
inline uint64_t splitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// SplitMix64 of one value: the output of a step from state x (x not kept).
inline uint64_t splitMix64Of(uint64_t x) { return splitMix64(x); }

class Pcg32 {
 public:
  Pcg32(uint64_t initState, uint64_t stream) : inc_((stream << 1u) | 1u) {
    nextUint();
    state_ += initState;
    nextUint();
  }

  /// The generator of unit `index` in a run seeded with `seed`.
  static Pcg32 forUnit(uint64_t seed, uint64_t index) {
    uint64_t mix = seed ^ splitMix64(index);
    const uint64_t initState = splitMix64(mix);
    const uint64_t stream = splitMix64(mix);
    return Pcg32(initState, stream);
  }

  /// The generator of stream `stream` in a sensor run seeded with `seed`
  /// (sensors::Rng; sensors::pixelStream makes the stream ids). Its own
  /// derivation, not forUnit's: the sensors' bytes were pinned with it.
  static Pcg32 forStream(uint64_t seed, uint64_t stream) {
    return Pcg32(splitMix64Of(seed + splitMix64Of(stream)),
                 splitMix64Of(stream ^ 0x5851F42D4C957F2Dull));
  }

  uint32_t nextUint() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorShifted >> rot) | (xorShifted << ((32u - rot) & 31u));
  }

  /// Uniform in [0, 1) with 24 random bits (exactly representable floats).
  float nextFloat() { return static_cast<float>(nextUint() >> 8) * 0x1.0p-24f; }

  /// Uniform in [0, 1) with 53 random bits, from two draws.
  double nextDouble() {
    const uint64_t hi = nextUint() >> 5;  // 27 bits
    const uint64_t lo = nextUint() >> 6;  // 26 bits
    return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
  }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

}  // namespace tofsim
