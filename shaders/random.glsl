// Stateless hashing for reproducible random numbers on the GPU: the same
// (seed, indices) give the same numbers whatever the thread schedule.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

uint hash3(uint a, uint b, uint c) { return pcgHash(a ^ pcgHash(b ^ pcgHash(c))); }

// Uniform in [0, 1) with 24 bits.
float unitFloat(uint bits) { return float(bits >> 8u) * (1.0 / 16777216.0); }
