// The camera G-buffer as the gathers read it: PIXEL_SAMPLES x PIXEL_SAMPLES
// sub-pixel samples per pixel (render.pixel_samples, a #define of the
// program), stored as a (width N) x (height N) image: sample s = j N + i of
// pixel (x, y) is texel (x N + i, y N + j), rasterized at the sub-pixel centre
// ((i + 1/2)/N - 1/2, (j + 1/2)/N - 1/2), the CPU backend's SurfaceImage
// order. With N = 1 it is the pixel-centre G-buffer of before.
//
// With ADAPTIVE_SAMPLES (render.adaptive_pixel_samples, N > 1) a per-pixel
// mask picks each pixel's samples: 1, its N x N sub-samples as above; 0, one
// sample read from the pixel-centre G-buffer (the W x H maps of
// pixel_samples: 1), standing for the whole pixel (weight 1, the whole pixel's
// footprint). Which maps a sample comes from is decided here only
// (samplesOfPixel, pixelSample), so both gathers sample the same pixels the
// same way.
#ifndef TOFSIM_SURFACE_SAMPLES_GLSL
#define TOFSIM_SURFACE_SAMPLES_GLSL

#ifndef PIXEL_SAMPLES
#define PIXEL_SAMPLES 1
#endif

#include "scatter_vertex.glsl"
const int kSamplesPerPixel = PIXEL_SAMPLES * PIXEL_SAMPLES;

// The vertices the G-buffers' texels name (their albedo's a): the scene's
// materials' (ir::materialVertices, index = material), then one per given
// sample (SurfaceMaps::load). A texel's vertex is its entry with what the
// material's textures give there (physics::texturedVertex).
layout(std430, binding = TOFSIM_SSBO_SCATTER_VERTICES) readonly buffer ScatterVertices {
  ScatterVertex scatterVertices[];
};

layout(binding = TOFSIM_UNIT_G_POSITION) uniform sampler2D uGPosition;
layout(binding = TOFSIM_UNIT_G_NORMAL) uniform sampler2D uGNormal;
layout(binding = TOFSIM_UNIT_G_ALBEDO) uniform sampler2D uGAlbedo;
#ifdef GLTF_MATERIALS
layout(binding = TOFSIM_UNIT_G_METALLIC_ROUGHNESS) uniform sampler2D uGMetallicRoughness;  // rg
#endif
uniform float uSampleWeight;  // 1 / PIXEL_SAMPLES^2: a sub-sample's share of the pixel

#ifdef ADAPTIVE_SAMPLES
layout(binding = TOFSIM_UNIT_CENTRE_POSITION) uniform sampler2D uCentrePosition;
layout(binding = TOFSIM_UNIT_CENTRE_NORMAL) uniform sampler2D uCentreNormal;
layout(binding = TOFSIM_UNIT_CENTRE_ALBEDO) uniform sampler2D uCentreAlbedo;
#ifdef GLTF_MATERIALS
layout(binding = TOFSIM_UNIT_CENTRE_METALLIC_ROUGHNESS) uniform sampler2D uCentreMetallicRoughness;
#endif
// Per pixel of the image (not of the segment): 1 = N x N samples, 0 = its centre.
layout(std430, binding = TOFSIM_SSBO_SAMPLED_PIXELS) readonly buffer SampledPixels {
  uint sampledPixels[];
};
#endif

#if defined(SAMPLE_CAMERA_ENDS) || defined(MEDIUM_REGIONS)
uniform uint uImagePixels;  // width x height: where the centre samples' records start

// Where sample s of image pixel `pixel` (which takes `samples`:
// samplesOfPixel) is in a buffer of one record per sample: pixel p's N x N
// samples at p N^2 + s, then with ADAPTIVE_SAMPLES one per pixel for the
// pixel-centre samples (camera_end.glsl's ends, region_legs.comp's legs).
uint sampleRecordIndex(uint pixel, int samples, int s) {
  uint i = pixel * uint(kSamplesPerPixel) + uint(s);
#if defined(ADAPTIVE_SAMPLES) && PIXEL_SAMPLES > 1
  if (samples == 1) i = uImagePixels * uint(kSamplesPerPixel) + pixel;
#endif
  return i;
}
#endif

// G-buffer texel of sample s of the pixel at image position pixelXy.
ivec2 sampleTexel(ivec2 pixelXy, int s) {
  return pixelXy * PIXEL_SAMPLES + ivec2(s % PIXEL_SAMPLES, s / PIXEL_SAMPLES);
}

// One sample's G-buffer texels and what it stands for.
struct SurfaceSample {
  vec4 position;         // xyz world, w = 1 on a surface, 0 else
  vec3 normal;           // unit, facing the camera
  ScatterVertex vertex;  // what it scatters (texelVertex)
  ivec2 pixel;      // the pixel's image position (a lens's steps are the pixel's own)
  float weight;     // share of the pixel: uSampleWeight, 1 for a whole-pixel sample
  bool wholePixel;  // its footprint is the whole pixel, not a sub-pixel (footprint_deposit.glsl)
};

// The vertex of a G-buffer texel whose albedo map holds `baseColor` (rgb
// texel, a vertex index) and metallic-roughness map `metallicRoughness`.
ScatterVertex texelVertex(vec4 baseColor, vec2 metallicRoughness) {
  return texturedVertex(scatterVertices[int(baseColor.a)], baseColor.rgb, metallicRoughness);
}

// Samples the pixel (image index `pixel`) takes, in order 0, 1, ...
int samplesOfPixel(uint pixel) {
#ifdef ADAPTIVE_SAMPLES
  if (sampledPixels[pixel] == 0u) return 1;
#endif
  return kSamplesPerPixel;
}

// Sample s of the pixel at image position xy, which takes `samples`
// (samplesOfPixel) samples.
SurfaceSample pixelSample(ivec2 xy, int samples, int s) {
  SurfaceSample o;
  o.pixel = xy;
#ifdef ADAPTIVE_SAMPLES
  // Only a masked-out pixel takes one sample when N > 1: the pixel_samples: 1
  // sample, from the centre maps.
  if (samples == 1) {
    o.position = texelFetch(uCentrePosition, xy, 0);
    o.normal = texelFetch(uCentreNormal, xy, 0).xyz;
#ifdef GLTF_MATERIALS
    vec2 mr = texelFetch(uCentreMetallicRoughness, xy, 0).rg;
#else
    vec2 mr = vec2(1.0);
#endif
    o.vertex = texelVertex(texelFetch(uCentreAlbedo, xy, 0), mr);
    o.weight = 1.0;
    o.wholePixel = true;
    return o;
  }
#endif
  ivec2 texel = sampleTexel(xy, s);
  o.position = texelFetch(uGPosition, texel, 0);
  o.normal = texelFetch(uGNormal, texel, 0).xyz;
#ifdef GLTF_MATERIALS
  vec2 mr = texelFetch(uGMetallicRoughness, texel, 0).rg;
#else
  vec2 mr = vec2(1.0);
#endif
  o.vertex = texelVertex(texelFetch(uGAlbedo, texel, 0), mr);
  o.weight = uSampleWeight;
  // With N = 1 the one sample is the whole pixel, and uSampleStepX/Y are its
  // steps: either choice of footprint steps gives the same numbers.
  o.wholePixel = false;
  return o;
}

#endif  // TOFSIM_SURFACE_SAMPLES_GLSL
