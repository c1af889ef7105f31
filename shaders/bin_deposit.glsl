// One contribution's share into one time bin of the gather's float histogram,
// or off the axis when the bin is outside it: physics::depositInBin
// (core/physics/include/tofsim/physics/FootprintBuffer.h), the same float
// operations. A point sample deposits its whole contribution (mass 1, and
// 1 x e is e exactly); a narrow footprint kernel a bin's mass
// (footprint_deposit.glsl).
//
// The including gather defines GATHER_HISTOGRAM (the name of its float volume
// array) and declares uBins.
#ifndef TOFSIM_BIN_DEPOSIT_GLSL
#define TOFSIM_BIN_DEPOSIT_GLSL

void depositInBin(uint local, int bin, float mass, vec3 energy, inout float lostBefore,
                  inout float lostAfter) {
  if (bin < 0 || bin >= uBins) {
    float lost = mass * (energy.r + energy.g + energy.b);
    if (bin < 0) {
      lostBefore += lost;
    } else {
      lostAfter += lost;
    }
    return;
  }
  uint i = (local * uint(uBins) + uint(bin)) * uint(TOFSIM_CHANNELS);
  GATHER_HISTOGRAM[i + 0u] += mass * energy.r;
  GATHER_HISTOGRAM[i + 1u] += mass * energy.g;
  GATHER_HISTOGRAM[i + 2u] += mass * energy.b;
}

#endif  // TOFSIM_BIN_DEPOSIT_GLSL
