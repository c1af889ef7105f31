// Per-region media (issue 42's `media:`, capture::MediumRegions on the CPU)
// as the GL passes see them: a program compiled with MEDIUM_REGIONS
// (gpu::gatherDefines, only where RenderSettings::media is not empty: every
// other render compiles the shaders of before) finds a leg's passage through
// the regions: its optical depth per channel (sum of sigma_t x length inside
// each region) and the path it adds to its time (sum (eta_r / eta_axis - 1) x
// length inside, geometric metres at the axis' index). Directions are not
// refracted at a region's boundary; regions neither overlap nor nest.
//
// A region's length inside a leg a -> b (t in [0, L] along unit d) comes from
// the crossings of the leg's whole line with the region's triangles (wound
// outwards), by a brute-force loop over them (regions are small closed
// meshes: render/GlRegionLimits.h bounds them). A closed mesh's inside
// indicator along the line is the sum of +1 at each entering crossing before
// t and -1 at each leaving one, so the length inside [0, L] is
//   sum over crossings of +-(L - clamp(t_c, 0, L)),
// which needs no sorting (MediumRegions walks the sorted crossings; the same
// length). A line through an edge or a vertex crosses several triangles at
// one point: each kind counts once there (a crossing within eps of a kept one
// of its kind is a repeat, as MediumRegions does), and the barycentric test
// has a little slack, so rounding makes a repeat of such a crossing, never a
// miss. The crossings kept per region are bounded (TOFSIM_REGION_CROSSINGS):
// a leg with more sets `overflow`, which the passes report as an error.
// Loop trips count into `iterations` (llvmpipe's guard: GlRegionLimits.h).
#ifndef TOFSIM_MEDIUM_REGIONS_GLSL
#define TOFSIM_MEDIUM_REGIONS_GLSL

#ifdef MEDIUM_REGIONS

struct Region {
  vec4 lo;          // xyz: the mesh's box min (world); w: extra path per metre inside
  vec4 hi;          // xyz: the box max; w: 0
  vec4 sigmaT;      // rgb: extinction sigma_a + sigma_s per metre; w: 0
  uvec4 triangles;  // x: its first triangle in regionCorners (3 corners each), y: its count
};
layout(std430, binding = TOFSIM_SSBO_REGIONS) readonly buffer Regions { Region regions[]; };
layout(std430, binding = TOFSIM_SSBO_REGION_CORNERS) readonly buffer RegionCorners {
  vec4 regionCorners[];
};
uniform uint uRegionCount;

const int kRegionCrossings = TOFSIM_REGION_CROSSINGS;
// Barycentric slack: a line through an edge is caught by both triangles
// (a repeat), not missed by both through rounding.
const float kBarycentricSlack = 1e-5;

struct RegionPassage {
  vec3 opticalDepth;  // per channel
  float extraPath_m;  // geometric metres at the axis' index
};

// Narrows [t0, t1] to where the leg is within one axis' slab of the box.
void clipToSlab(float o, float d, float lo, float hi, inout float t0, inout float t1) {
  if (d == 0.0) {
    if (o < lo || o > hi) t1 = -1.0;  // beside the slab: no t
    return;
  }
  float ta = (lo - o) / d, tb = (hi - o) / d;
  t0 = max(t0, min(ta, tb));
  t1 = min(t1, max(ta, tb));
}

// Whether the leg o + t d, t in [0, len], stays outside region r's box
// (grown a little): then it is nowhere inside the region.
bool legMissesBox(Region r, vec3 o, vec3 d, float len) {
  vec3 margin = 1e-4 * (r.hi.xyz - r.lo.xyz) + vec3(1e-6);
  vec3 lo = r.lo.xyz - margin, hi = r.hi.xyz + margin;
  float t0 = 0.0, t1 = len;
  clipToSlab(o.x, d.x, lo.x, hi.x, t0, t1);
  clipToSlab(o.y, d.y, lo.y, hi.y, t0, t1);
  clipToSlab(o.z, d.z, lo.z, hi.z, t0, t1);
  return t0 > t1;
}

// Moeller-Trumbore on the whole line o + t d (any t): where it crosses
// triangle `tri` of regionCorners, and whether against the outward normal.
bool lineCrossesTriangle(vec3 o, vec3 d, uint tri, out float t, out bool entering) {
  vec3 a = regionCorners[3u * tri].xyz;
  vec3 e1 = regionCorners[3u * tri + 1u].xyz - a;
  vec3 e2 = regionCorners[3u * tri + 2u].xyz - a;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  t = 0.0;
  entering = false;
  if (det == 0.0) return false;  // parallel: the line grazes, no crossing
  float inv = 1.0 / det;
  vec3 s = o - a;
  float u = dot(s, p) * inv;
  if (u < -kBarycentricSlack || u > 1.0 + kBarycentricSlack) return false;
  vec3 q = cross(s, e1);
  float v = dot(d, q) * inv;
  if (v < -kBarycentricSlack || u + v > 1.0 + kBarycentricSlack) return false;
  t = dot(e2, q) * inv;
  entering = dot(d, cross(e1, e2)) < 0.0;
  return true;
}

// The length of o + t d, t in [0, len], inside region r (its box touched).
float lengthInside(Region r, vec3 o, vec3 d, float len, inout uint iterations,
                   inout bool overflow) {
  // Repeats of one crossing differ by rounding: float's on the corners' and
  // the leg's scale.
  float eps = 1e-5 * (1.0 + length(r.hi.xyz - r.lo.xyz) + len);
  float keptT[kRegionCrossings];
  bool keptEntering[kRegionCrossings];
  int kept = 0;
  float inside = 0.0;
  uint end = r.triangles.x + r.triangles.y;
  for (uint tri = r.triangles.x; tri < end; ++tri) {
    ++iterations;
    float t;
    bool entering;
    if (!lineCrossesTriangle(o, d, tri, t, entering)) continue;
    bool repeat = false;
    for (int k = 0; k < kept; ++k) {
      ++iterations;
      repeat = repeat || (keptEntering[k] == entering && abs(keptT[k] - t) <= eps);
    }
    if (repeat) continue;
    if (kept == kRegionCrossings) {
      overflow = true;
      continue;
    }
    keptT[kept] = t;
    keptEntering[kept] = entering;
    ++kept;
    inside += (entering ? 1.0 : -1.0) * (len - clamp(t, 0.0, len));
  }
  // Rounding only: the sum of a closed mesh's crossings is in [0, len].
  return clamp(inside, 0.0, len);
}

// The leg a -> b's passage through the regions.
RegionPassage regionPassage(vec3 a, vec3 b, inout uint iterations, inout bool overflow) {
  RegionPassage p;
  p.opticalDepth = vec3(0.0);
  p.extraPath_m = 0.0;
  vec3 ab = b - a;
  float len = length(ab);
  if (!(len > 0.0)) return p;
  vec3 d = ab / len;
  for (uint i = 0u; i < uRegionCount; ++i) {
    ++iterations;
    Region r = regions[i];
    if (legMissesBox(r, a, d, len)) continue;
    float inside = lengthInside(r, a, d, len, iterations, overflow);
    p.opticalDepth += r.sigmaT.rgb * inside;
    p.extraPath_m += r.lo.w * inside;
  }
  return p;
}

// exp(-optical depth) per channel.
vec3 regionTransmittance(RegionPassage p) { return exp(-p.opticalDepth); }

#endif  // MEDIUM_REGIONS

#endif  // TOFSIM_MEDIUM_REGIONS_GLSL
