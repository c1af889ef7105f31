// The camera G-buffer as the gathers read it: PIXEL_SAMPLES x PIXEL_SAMPLES
// sub-pixel samples per pixel (render.pixel_samples, a #define of the
// program), stored as a (width N) x (height N) image: sample s = j N + i of
// pixel (x, y) is texel (x N + i, y N + j), rasterized at the sub-pixel centre
// ((i + 1/2)/N - 1/2, (j + 1/2)/N - 1/2), the CPU backend's SurfaceImage
// order. With N = 1 it is the pixel-centre G-buffer of before.
#ifndef TOFSIM_SURFACE_SAMPLES_GLSL
#define TOFSIM_SURFACE_SAMPLES_GLSL

#ifndef PIXEL_SAMPLES
#define PIXEL_SAMPLES 1
#endif
const int kSamplesPerPixel = PIXEL_SAMPLES * PIXEL_SAMPLES;

layout(binding = TOFSIM_UNIT_G_POSITION) uniform sampler2D uGPosition;
layout(binding = TOFSIM_UNIT_G_NORMAL) uniform sampler2D uGNormal;
layout(binding = TOFSIM_UNIT_G_ALBEDO) uniform sampler2D uGAlbedo;
#ifdef GLTF_MATERIALS
layout(binding = TOFSIM_UNIT_G_METALLIC_ROUGHNESS) uniform sampler2D uGMetallicRoughness;  // rg
#endif

// G-buffer texel of sample s of the pixel at image position pixelXy.
ivec2 sampleTexel(ivec2 pixelXy, int s) {
  return pixelXy * PIXEL_SAMPLES + ivec2(s % PIXEL_SAMPLES, s / PIXEL_SAMPLES);
}

#endif  // TOFSIM_SURFACE_SAMPLES_GLSL
