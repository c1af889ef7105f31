// A pixel sample's camera ray as the medium passes integrate along it
// (issue 42: medium_direct.comp, the light's single scattering;
// medium_vpls.comp, the VPLs'): its camera end (camera_end.glsl), its
// direction (uMediumRays: ir::sampleRay's, laid out as the camera ends,
// MediumDirect.cpp), its first surface (surface_samples.glsl) and its share
// of the pixel. Include after camera_end.glsl, with uImageWidth and
// uCameraUnwarp declared.
#ifndef TOFSIM_MEDIUM_SAMPLE_RAYS_GLSL
#define TOFSIM_MEDIUM_SAMPLE_RAYS_GLSL

// One vec4 (xyz unit direction) per sample: pixel p's N x N at p N^2 + s,
// then with ADAPTIVE_SAMPLES one per pixel centre from uMediumImagePixels N^2.
layout(std430, binding = TOFSIM_SSBO_MEDIUM_RAYS) readonly buffer MediumRays {
  vec4 mediumRays[];
};
uniform uint uMediumImagePixels;

// Sample s's ray direction (the pixel takes `samples` samples).
vec3 mediumRayDirection(ivec2 xy, int samples, int s) {
  uint pixel = uint(xy.y * uImageWidth + xy.x);
  uint i = pixel * uint(kSamplesPerPixel) + uint(s);
#if defined(ADAPTIVE_SAMPLES) && PIXEL_SAMPLES > 1
  if (samples == 1) i = uMediumImagePixels * uint(kSamplesPerPixel) + pixel;
#endif
  return mediumRays[i].xyz;
}

// Sample s's ray toward an emitter at `emitter` of radius `radius`
// (medium.glsl's mediumEmitterRay), and its share of the pixel in `weight`,
// as direct_gather.comp weighs it.
MediumRay mediumSampleRay(ivec2 xy, int samples, int s, vec3 emitter, float radius,
                          out float weight) {
  SurfaceSample g = pixelSample(xy, samples, s);
  CameraEnd end = cameraEndOf(xy, samples, s);
  vec3 origin = end.position;
  float surface = g.position.w != 0.0 ? length(g.position.xyz - origin) : MEDIUM_UNBOUNDED;
#ifdef SAMPLE_CAMERA_ENDS
  float lensPath = uCameraUnwarp != 0 ? 0.0 : end.lensPath_m;
#else
  float lensPath = 0.0;
#endif
#if PIXEL_SAMPLES > 1
  weight = g.weight;
#else
  weight = 1.0;
#endif
  return mediumEmitterRay(origin, mediumRayDirection(xy, samples, s), emitter, radius, surface,
                          lensPath);
}

#endif  // TOFSIM_MEDIUM_SAMPLE_RAYS_GLSL
