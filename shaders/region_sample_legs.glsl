// Per-region media (issue 42's `media:`): a G-buffer sample's camera and
// light legs through the regions, as region_legs.comp found them once per
// render, read by the gathers (a program compiled with MEDIUM_REGIONS).
// Include after surface_samples.glsl.
#ifndef TOFSIM_REGION_SAMPLE_LEGS_GLSL
#define TOFSIM_REGION_SAMPLE_LEGS_GLSL

#ifdef MEDIUM_REGIONS
layout(std430, binding = TOFSIM_SSBO_REGION_LEGS) readonly buffer RegionLegs {
  vec4 regionLegs[];
};

struct SampleLegs {
  vec3 cameraT;         // the x -> camera leg's transmittance
  float cameraExtra_m;  // the path it adds (geometric metres at the axis' index)
  vec3 lightT;          // the light -> x leg's
  float lightExtra_m;
};

// The legs of sample s of image pixel `pixel`, which takes `samples`.
SampleLegs sampleLegs(uint pixel, int samples, int s) {
  uint i = sampleRecordIndex(pixel, samples, s);
  vec4 camera = regionLegs[2u * i], light = regionLegs[2u * i + 1u];
  SampleLegs o;
  o.cameraT = camera.rgb;
  o.cameraExtra_m = camera.w;
  o.lightT = light.rgb;
  o.lightExtra_m = light.w;
  return o;
}
#endif

#endif  // TOFSIM_REGION_SAMPLE_LEGS_GLSL
