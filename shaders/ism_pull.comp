#version 450 core
// Pull step of pull-push hole filling: a texel of the coarser level is the
// mean of its finer children that hold a depth (empty = +inf).
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

layout(std430, binding = TOFSIM_SSBO_ISM) buffer Ism { float ism[]; };

uniform uint uVplCount;
uniform uint uVplStride;
uniform uint uFineOffset;
uniform int uFineSize;
uniform uint uCoarseOffset;
uniform int uCoarseSize;

void main() {
  uint id = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  uint perVpl = uint(uCoarseSize * uCoarseSize);
  if (id >= uVplCount * perVpl) return;
  uint v = id / perVpl, t = id % perVpl;
  ivec2 c = ivec2(int(t) % uCoarseSize, int(t) / uCoarseSize);
  float sum = 0.0;
  int count = 0;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      ivec2 f = 2 * c + ivec2(dx, dy);
      if (f.x >= uFineSize || f.y >= uFineSize) continue;
      float value = ism[v * uVplStride + uFineOffset + uint(f.y * uFineSize + f.x)];
      if (!isinf(value)) { sum += value; ++count; }
    }
  }
  ism[v * uVplStride + uCoarseOffset + t] = count > 0 ? sum / float(count) : uintBitsToFloat(0x7f800000u);
}
