#pragma once
// Private to the config module: the run config's parameter tables, in the
// vocabulary of the sensor tables (sensors/ParamField.h), visited by the same
// parse, emit and doc functions (Field*.h). Defaults are the structs'
// initialisers. So far `render.indirect` and `render.reference`; the other sections are still
// hand-written in RunConfigLoader.cpp and EffectiveConfig.cpp because their
// defaults are literals in the parser, not struct initialisers, and their keys
// mix vectors, angles and cross-field checks.

#include <array>
#include <tuple>

#include "tofsim/capture/RenderSettings.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

using sensors::Choice;
using sensors::Field;
using sensors::Flag;
using sensors::IntegerIn;
using sensors::kAnyValue;
using sensors::Name;
using sensors::Number;

inline constexpr std::array<Name<capture::Visibility>, 2> kVisibilityNames{
    {{"ism", capture::Visibility::Ism}, {"exact", capture::Visibility::Exact}}};

// clang-format off
inline constexpr auto kIndirectFields = std::tuple{
    Field{"enabled", &capture::IndirectSettings::enabled, Flag{},
          {.doc = "render indirect light"}},
    Field{"rsm_resolution", &capture::IndirectSettings::rsm_resolution, IntegerIn{1, 4096},
          {.unit = "pixel", .doc = "reflective shadow map side; VPLs = its square per light view (one view for spots up to 60° half angle, six cube faces otherwise; texels that see no lit surface make none, a texel at an edge may make more: `rsm_edge_samples`); at most 4,194,304 texels over the views"}},
    Field{"rsm_edge_samples", &capture::IndirectSettings::rsm_edge_samples, IntegerIn{1, 16},
          {.doc = "N: an RSM texel at an edge (a silhouette, a crease or a depth jump in its 3 x 3 neighbourhood, the test of `adaptive_pixel_samples`) is traced at N x N sub-texels and makes one VPL per flat surface among them, with their summed flux: the first bounce's energy right at the RSM's edges (README.md, \"How it renders\", VPLs). N is lowered so that N `rsm_resolution` <= 2048; 1 = one VPL per texel, at its centre"}},
    Field{"merge_pixel_samples", &capture::IndirectSettings::merge_pixel_samples, Flag{},
          {.doc = "with `pixel_samples` N > 1: a pixel gathers its indirect light once per flat surface among its N x N samples (the test of `adaptive_pixel_samples`), weighted by the samples it covers, its footprint their bounding box, instead of once per sample; the direct light keeps every sample. An edge pixel's coverage at about the cost of one sample per surface (bench/README.md, \"Merged pixel samples\"). `render.backend: cpu` (`auto` picks it); not with `camera.aperture` > 0 or `materials: gltf` (there every sample gathers)"}},
    Field{"ism_resolution", &capture::IndirectSettings::ism_resolution, IntegerIn{4, 4096},
          {.unit = "pixel", .doc = "side of each VPL's paraboloid depth map"}},
    Field{"points_per_vpl", &capture::IndirectSettings::points_per_vpl, IntegerIn{0, 1 << 24},
          {.doc = "ISM points splatted per VPL; 0 = two per texel of the map, 2 `ism_resolution`^2 (2048 at 32), where the ISM's late light is within 1 % of exact visibility's: sparser maps leak light through occluders, denser ones hide it where surfaces meet (bench/README.md, \"The ISM's bias\")"}},
    Field{"ism_pull_push", &capture::IndirectSettings::ism_pull_push, Flag{},
          {.doc = "fill ISM holes by pull-push"}},
    Field{"visibility", &capture::IndirectSettings::visibility, Choice<capture::Visibility>{kVisibilityNames},
          {.doc = "VPL visibility: `ism` (imperfect shadow maps) or `exact`"}},
    Field{"geometry_clamp", &capture::IndirectSettings::geometry_term_clamp_per_m2, Number{kAnyValue},
          {.unit = "1/m^2", .doc = "upper bound of a point VPL's cos cos / d^2; within 8 patch widths of a first-bounce VPL the gather takes its RSM texel patch's exact integral instead, bounded by pi / A and not clamped (README.md, \"Indirect gather\"); <= 0 disables clamping"}},
    Field{"vpl_brdf_clamp", &capture::IndirectSettings::vpl_brdf_clamp_per_sr, Number{kAnyValue},
          {.unit = "1/sr", .doc = "`materials: gltf`: upper bound of each channel of a VPL's BRDF value toward the point it lights (and of its BRDF weight where a later bounce continues its path): bounds the spikes of smooth VPLs, at the cost of the energy above it (README.md, \"Materials\", measured bias); <= 0 disables clamping"}},
    Field{"vpl_footprint", &capture::IndirectSettings::vpl_footprint, Flag{},
          {.doc = "spread each VPL's light over the path variation across its RSM texel's patch (no temporal banding from few VPLs); only with `pixel_footprint: true`"}},
    Field{"bounces", &capture::IndirectSettings::bounces, IntegerIn{1, 8},
          {.doc = "indirect bounces: 1 = the RSM's VPLs only; k adds VPLs of bounces 2..k, each traced (Embree) from the VPLs of the bounce before, in a cosine-weighted direction (with `materials: gltf`, sampled from the VPL's BRDF, README.md \"Materials\"); `indirect` holds all bounces. Compare with `reference.bounces: k + 1`"}},
    Field{"vpls_per_bounce", &capture::IndirectSettings::vpls_per_bounce, IntegerIn{0, 1 << 22},
          {.doc = "VPLs traced for each bounce after the first (chosen among the bounce before's in proportion to their power); 0 = as many as the first bounce has; rays that leave the scene make none. The total of all bounces is at most 4,194,304"}},
    Field{"russian_roulette", &capture::IndirectSettings::russian_roulette, Flag{},
          {.doc = "Russian roulette on bounces 2..k: a traced VPL survives with probability q = the largest albedo channel at its hit, its flux divided by q (unbiased), and each bounce after the second traces as many rays as the bounce before kept VPLs; fewer VPLs, more noise. `false`: every later bounce traces `vpls_per_bounce`"}},
};

inline constexpr std::array<Name<ReferencePixelFilter>, 2> kPixelFilterNames{
    {{"box", ReferencePixelFilter::Box}, {"point", ReferencePixelFilter::Point}}};
inline constexpr std::array<Name<ReferenceSampling>, 2> kReferenceSamplingNames{
    {{"brdf", ReferenceSampling::Brdf}, {"cosine", ReferenceSampling::Cosine}}};

inline constexpr auto kReferenceFields = std::tuple{
    Field{"bounces", &ReferenceConfig::bounces, IntegerIn{1, 64},
          {.doc = "surface interactions per path: 1 direct only, 2 direct + one indirect bounce, n"}},
    Field{"samples_per_pixel", &ReferenceConfig::samples_per_pixel, IntegerIn{1, 1 << 24},
          {.doc = "paths per pixel (with `pixel_filter: box`, also the direct term's sub-pixel samples)"}},
    Field{"threads", &ReferenceConfig::threads, IntegerIn{0, 4096},
          {.doc = "worker threads, 0 = every core this process may run on (its CPU affinity)"}},
    Field{"pixel_filter", &ReferenceConfig::pixel_filter, Choice<ReferencePixelFilter>{kPixelFilterNames},
          {.doc = "`box`: a pixel integrates its area (stratified, jittered sub-pixel points, one per path); "
                  "`point`: one ray through the pixel centre, the G-buffer's view (closed-form tests)"}},
    Field{"sampling", &ReferenceConfig::sampling, Choice<ReferenceSampling>{kReferenceSamplingNames},
          {.doc = "continuation at glTF surfaces (`render.materials: gltf`): `brdf` draws from a mixture of the cosine lobe and GGX visible normals weighted by the mixture's pdf (one-sample MIS); `cosine`: cosine sampling weighted by pi f (noisier on glossy surfaces; the bytes of before). Lambertian surfaces are cosine-sampled either way"}},
};

inline constexpr std::array<Name<OutputFormat>, 2> kOutputFormatNames{
    {{"npy", OutputFormat::Npy}, {"hdf5", OutputFormat::Hdf5}}};

// The keys of `output` declared here; the others are hand-written.
inline constexpr auto kOutputFields = std::tuple{
    Field{"format", &OutputConfig::format, Choice<OutputFormat>{kOutputFormatNames},
          {.doc = "`npy`: each array its own `.npy` (`transient.npy`, `direct.npy`, ...); `hdf5`: the volumes, `depth`, `steady` and every sensor array as datasets of one `capture.h5`, chunked along the pixels, shuffle + gzip, each with its metadata as attributes (README.md, \"What a render writes\"); the EXR and PNG pictures and the JSON files stay. An `nlos` capture writes its own files either way"}},
};
// clang-format on

}  // namespace tofsim::config
