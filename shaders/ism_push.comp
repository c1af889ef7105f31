#version 450 core
// Push step of pull-push hole filling: an empty finer texel takes the value
// of its coarser parent.
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
  uint perVpl = uint(uFineSize * uFineSize);
  if (id >= uVplCount * perVpl) return;
  uint v = id / perVpl, t = id % perVpl;
  uint index = v * uVplStride + uFineOffset + t;
  if (!isinf(ism[index])) return;
  ivec2 f = ivec2(int(t) % uFineSize, int(t) / uFineSize);
  ivec2 c = f / 2;
  ism[index] = ism[v * uVplStride + uCoarseOffset + uint(c.y * uCoarseSize + c.x)];
}
