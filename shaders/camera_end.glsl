// Where a sample's camera leg ends, and the path a lens adds after it: the
// imager's viewpoint (uCameraPosition_world, no lens path) for every sample,
// or with SAMPLE_CAMERA_ENDS each given sample's own (ir::SurfaceImage::
// aperture, the CPU backend's SurfaceImage::cameraOf and lensPathOf): a ray
// list's ray origins. The buffer holds one vec4 (xyz end, w lens path) per
// sample, at surface_samples.glsl's sampleRecordIndex.
// The including gather declares uImageWidth.
#ifndef TOFSIM_CAMERA_END_GLSL
#define TOFSIM_CAMERA_END_GLSL

uniform vec3 uCameraPosition_world;
#ifdef SAMPLE_CAMERA_ENDS
layout(std430, binding = TOFSIM_SSBO_SAMPLE_CAMERA_ENDS) readonly buffer SampleCameraEnds {
  vec4 sampleCameraEnds[];
};
#endif

struct CameraEnd {
  vec3 position;      // world
  float lensPath_m;   // the lens's path after it (0 without a lens)
};

// Sample s of the pixel at image position xy, which takes `samples`
// (samplesOfPixel) samples.
CameraEnd cameraEndOf(ivec2 xy, int samples, int s) {
  CameraEnd o;
#ifdef SAMPLE_CAMERA_ENDS
  uint i = sampleRecordIndex(uint(xy.y * uImageWidth + xy.x), samples, s);
  o.position = sampleCameraEnds[i].xyz;
  o.lensPath_m = sampleCameraEnds[i].w;
#else
  o.position = uCameraPosition_world;
  o.lensPath_m = 0.0;
#endif
  return o;
}

#endif  // TOFSIM_CAMERA_END_GLSL
