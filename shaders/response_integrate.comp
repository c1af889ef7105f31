#version 450 core
// The temporal-response stage on GL (core/physics/temporal_response.md): one
// thread per pixel of the segment runs one stage of one delayed class: the
// first stage turns the class's difference buffer (its region of the
// footprint buffer) into the class's bin integrals x by a double prefix sum;
// each stage filters its input by one member's kernel; a middle stage stores
// its output in another region (the scratch region and the class's own, in
// turn), the last one adds it to the volume and books the light the kernels
// carry past the last bin in the pixel's light after the axis.
// physics::applyResponse (TemporalResponse.h) with the per-bin arithmetic of
// temporal_response.glsl, in the same order, so the bytes equal the CPU's for
// the same buffer.
//
// x[n] replaces the buffer's entry n as it is computed (the taps of the later
// bins read it); the renderer clears the class regions after the last chunk.
// llvmpipe ends every loop of an invocation after 65535 iterations, so the
// renderer covers the axis in chunks of bins [uFirstBin, uFirstBin +
// uBinCount), (1 + taps) iterations a bin; between chunks the running sums
// wait in the pixel's state (slope, value, tail, sum in, sum out); between
// stages the sum in (what the output would hold on an endless axis).
#include "temporal_response.glsl"

layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

layout(std430, binding = TOFSIM_SSBO_FOOTPRINT) buffer FootprintDiff { double footprintDiff[]; };
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT_WRITTEN) buffer FootprintWritten {
  uint footprintWritten[];
};
layout(std430, binding = TOFSIM_SSBO_FOOTPRINT_VOLUME) buffer Volume { float histogram[]; };
// Two floats per pixel: light before / after the axis.
layout(std430, binding = TOFSIM_SSBO_OUTSIDE_AXIS) buffer OutsideAxis { float outside[]; };
// Per pixel: 16 doubles, the running sums between chunks.
layout(std430, binding = TOFSIM_SSBO_RESPONSE_STATE) buffer ResponseState { double state[]; };
// Per stage from uTapsOffset: prompt, tail ratio, tail weight, the
// re-emission matrix (9, column by column), then the taps.
layout(std430, binding = TOFSIM_SSBO_RESPONSE_TAPS) readonly buffer ResponseTaps {
  double responseTaps[];
};

uniform uint uPixelCount;
uniform int uBins;
uniform int uFirstBin;  // first bin of this chunk
uniform int uBinCount;  // bins of this chunk
uniform uint uRegion;   // the class's region: class x pixels per region
uniform uint uInput;    // the stage's input region (pixels): uRegion for the first stage
uniform uint uOutput;   // a middle stage's output region (pixels)
uniform int uFirstStage;  // the input is the difference buffer
uniform int uLastStage;   // the output goes to the volume
uniform int uReemits;     // the kernel's matrix is not the identity
uniform int uDelay;     // the first tap's delay, bins
uniform int uTapCount;
uniform uint uTapsOffset;

dvec3 loadX(uint base, int k) {
  uint i = base + uint(k * TOFSIM_CHANNELS);
  return dvec3(footprintDiff[i], footprintDiff[i + 1u], footprintDiff[i + 2u]);
}

dvec3 loadState(uint s, int which) {
  uint i = s + uint(3 * which);
  return dvec3(state[i], state[i + 1u], state[i + 2u]);
}

void storeState(uint s, int which, dvec3 v) {
  uint i = s + uint(3 * which);
  state[i] = v.x;
  state[i + 1u] = v.y;
  state[i + 2u] = v.z;
}

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount) return;
  uint region = uRegion + local;
  if (footprintWritten[region] == 0u) return;
  uint base = (uInput + local) * uint(uBins) * uint(TOFSIM_CHANNELS);
  uint outBase = (uOutput + local) * uint(uBins) * uint(TOFSIM_CHANNELS);
  uint out0 = local * uint(uBins) * uint(TOFSIM_CHANNELS);
  uint s = local * 16u;
  dvec3 slope = dvec3(0.0lf), value = dvec3(0.0lf), tail = dvec3(0.0lf);
  dvec3 sumIn = dvec3(0.0lf), sumOut = dvec3(0.0lf);
  if (uFirstBin > 0) {
    slope = loadState(s, 0);
    value = loadState(s, 1);
    tail = loadState(s, 2);
    sumIn = loadState(s, 3);
    sumOut = loadState(s, 4);
  } else if (uFirstStage == 0) {
    sumIn = loadState(s, 3);
  }
  double prompt = responseTaps[uTapsOffset];
  double ratio = responseTaps[uTapsOffset + 1u];
  double weight = responseTaps[uTapsOffset + 2u];
  dmat3 m;
  for (int c = 0; c < 3; ++c) {
    uint k = uTapsOffset + 3u + uint(3 * c);
    m[c] = dvec3(responseTaps[k], responseTaps[k + 1u], responseTaps[k + 2u]);
  }
  uint tapsAt = uTapsOffset + 12u;
  int end = min(uFirstBin + uBinCount, uBins);
  for (int n = uFirstBin; n < end; ++n) {
    uint i = base + uint(n * TOFSIM_CHANNELS);
    if (uFirstStage != 0) {
      slope += dvec3(footprintDiff[i], footprintDiff[i + 1u], footprintDiff[i + 2u]);
      value += slope;
      footprintDiff[i] = value.x;
      footprintDiff[i + 1u] = value.y;
      footprintDiff[i + 2u] = value.z;
    } else {
      value = dvec3(footprintDiff[i], footprintDiff[i + 1u], footprintDiff[i + 2u]);
    }
    dvec3 fir = dvec3(0.0lf);
    for (int j = 0; j < uTapCount; ++j) {
      int k = n - uDelay - j;
      if (k < 0) break;
      fir = responseFirTerm(fir, responseTaps[tapsAt + uint(j)], loadX(base, k));
    }
    int entering = n - uDelay - uTapCount;
    tail = responseTail(ratio, weight, tail, entering >= 0 ? loadX(base, entering) : dvec3(0.0lf));
    dvec3 y = uReemits != 0 ? responseReemittedOutput(prompt, value, fir, tail, m)
                            : responseOutput(prompt, value, fir, tail);
    if (uLastStage != 0) {
      uint h = out0 + uint(n * TOFSIM_CHANNELS);
      histogram[h] += float(y.x);
      histogram[h + 1u] += float(y.y);
      histogram[h + 2u] += float(y.z);
    } else {
      uint o = outBase + uint(n * TOFSIM_CHANNELS);
      footprintDiff[o] = y.x;
      footprintDiff[o + 1u] = y.y;
      footprintDiff[o + 2u] = y.z;
    }
    if (uFirstStage != 0) sumIn += value;
    if (uLastStage != 0) sumOut += y;
  }
  if (end < uBins) {
    storeState(s, 0, slope);
    storeState(s, 1, value);
    storeState(s, 2, tail);
    storeState(s, 3, sumIn);
    storeState(s, 4, sumOut);
    return;
  }
  if (uReemits != 0) sumIn = responseExpected(prompt, m, sumIn);
  if (uLastStage == 0) {
    storeState(s, 3, sumIn);  // for the next stage
    return;
  }
  double past = (sumIn.x - sumOut.x) + (sumIn.y - sumOut.y) + (sumIn.z - sumOut.z);
  if (past > 0.0lf) outside[2u * local + 1u] += float(past);
  footprintWritten[region] = 0u;
}
