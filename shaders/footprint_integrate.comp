#version 450 core
// The pixel footprint's final pass (footprint_kernel.md): one thread per pixel
// of the segment turns its difference buffer into bin integrals by a double
// prefix sum and adds them to the volume bound at TOFSIM_SSBO_FOOTPRINT_VOLUME,
// zeroing the buffer and its written flag behind it so that the next gathers
// start clean. The order of physics::integrateFootprint (FootprintBuffer.h):
// per channel, slope += diff; value += slope; histogram += float(value), bins
// ascending, in double; so the bytes equal the CPU's for the same buffer.
//
// llvmpipe ends every loop of an invocation after 65535 iterations, so the
// renderer covers the axis in chunks of bins [uFirstBin, uFirstBin +
// uBinCount), one dispatch each, in increasing order. Between chunks the
// running sums (slope, value) of each channel wait, as exact doubles, in the
// chunk's last two entries, which are consumed (zero) by then.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

layout(std430, binding = TOFSIM_SSBO_FOOTPRINT) buffer FootprintDiff { double footprintDiff[]; };
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT_WRITTEN) buffer FootprintWritten {
  uint footprintWritten[];
};
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT_VOLUME) buffer Volume { float histogram[]; };

uniform uint uPixelCount;
uniform int uBins;
uniform int uFirstBin;  // first bin of this chunk
uniform int uBinCount;  // bins of this chunk (>= 2 unless it is the whole axis)

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount || footprintWritten[local] == 0u) return;
  uint base = local * uint(uBins) * uint(TOFSIM_CHANNELS);
  int end = min(uFirstBin + uBinCount, uBins);
  for (int c = 0; c < TOFSIM_CHANNELS; ++c) {
    double slope = 0.0lf;  // first prefix sum: I_k - I_(k-1)
    double value = 0.0lf;  // second prefix sum: I_k
    if (uFirstBin > 0) {   // the previous chunk's sums
      uint s = base + uint((uFirstBin - 2) * TOFSIM_CHANNELS + c);
      uint v = base + uint((uFirstBin - 1) * TOFSIM_CHANNELS + c);
      slope = footprintDiff[s];
      value = footprintDiff[v];
      footprintDiff[s] = 0.0lf;
      footprintDiff[v] = 0.0lf;
    }
    for (int k = uFirstBin; k < end; ++k) {
      uint i = base + uint(k * TOFSIM_CHANNELS + c);
      slope += footprintDiff[i];
      value += slope;
      histogram[i] += float(value);
      footprintDiff[i] = 0.0lf;
    }
    if (end < uBins) {
      footprintDiff[base + uint((end - 2) * TOFSIM_CHANNELS + c)] = slope;
      footprintDiff[base + uint((end - 1) * TOFSIM_CHANNELS + c)] = value;
    }
  }
  if (end == uBins) footprintWritten[local] = 0u;
}
