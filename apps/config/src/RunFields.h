#pragma once
// Private to the config module: the run config's parameter tables, in the
// vocabulary of the sensor tables (sensors/ParamField.h, and FieldKinds.h for
// the kinds only a run has), visited by the same parse, emit and doc
// functions (Field*.h): each key's name, kind, range, unit and doc are
// written here once; its default is the struct's initialiser. This file:
// `render`, `render.indirect` and `render.reference`; CameraFields.h,
// RaysFields.h, TimeFields.h, LightFields.h and OutputFields.h the others.

#include <array>
#include <tuple>

#include "FieldKinds.h"
#include "tofsim/capture/RenderSettings.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

using sensors::Choice;
using sensors::Custom;
using sensors::Field;
using sensors::Flag;
using sensors::IntegerIn;
using sensors::kAnyValue;
using sensors::Name;
using sensors::Number;
using sensors::kPositive;
using sensors::Text;

inline constexpr std::array<Name<capture::Visibility>, 2> kVisibilityNames{
    {{"ism", capture::Visibility::Ism}, {"exact", capture::Visibility::Exact}}};

// clang-format off
inline constexpr auto kIndirectFields = std::tuple{
    Field{"enabled", &capture::IndirectSettings::enabled, Flag{},
          {.doc = "render indirect light"}},
    Field{"rsm_resolution", &capture::IndirectSettings::rsm_resolution, IntegerIn{1, 4096},
          {.unit = "pixel", .doc = "reflective shadow map side; VPLs = its square per light view (one view for spots up to 60° half angle, six cube faces otherwise; texels that see no lit surface make none, a texel at an edge may make more: `rsm_edge_samples`); at most 4,194,304 texels over the views"}},
    Field{"medium_vpls", &capture::IndirectSettings::medium_vpls, IntegerIn{0, 1 << 22},
          {.doc = "with a scattering `medium` (`sigma_s` > 0) or region (`media`, CPU backend): rays from the light, drawn from its emission profile, each leaving one medium VPL where it scatters before any surface (in a region: rays that cross no scattering region leave none) (a free-flight distance; its flux the power extinguished there, its phase function the medium's), bounce 1 with the RSM's VPLs; later bounces may scatter in the medium too. 0 = none; the default 1024 is the default RSM's VPL count (32^2). Ignored without a scattering medium or region (core/physics/medium_vpls.md)"}},
    Field{"medium_camera_rays", &capture::IndirectSettings::medium_camera_rays, Flag{},
          {.doc = "with a scattering `medium` or region (`media`: along the rays' stretches inside the regions): every VPL's light (the RSM's, the medium's, later bounces') scattered once more into the pixels' camera rays, per time bin (core/physics/medium_vpl_scattering.md): the medium's multiple scattering seen along the rays. Sampled: a roulette keeps about 4096 (ray, VPL) pairs a ray, each lit at 2 points (unbiased; its noise falls with the VPLs and pixels); configs/fog_lidar.yaml (64 x 64 x 1100 bins) takes 4.2 CPU-s with it against 2.6 without, sensors included; false: the rays see the light source's single scattering only, and the multiple scattering only where it lights surfaces. Ignored without a scattering medium or region"}},
    Field{"gather_pairs", &capture::IndirectSettings::gather_pairs, IntegerIn{0, 1 << 24},
          {.doc = "N > 0: the indirect gather at the surfaces (and medium pixels) keeps about N (pixel sample, VPL) pairs a sample by a roulette on what each can bring (the VPL's mean flux over the squared distance; the nearest and brightest always kept), weighing a kept pair's light by 1 / its probability, so visibility, scattered radiance and deposit run for the kept pairs only: unbiased, its noise falls with N and the pixels (core/physics/medium_vpl_scattering.md, \"The surface gather sampled\"). For many VPLs whose light at the surfaces is smooth: configs/fog_box.yaml keeps 512 of its 22,807. 0 = every pair. `render.backend: cpu` (`auto` picks it)"}},
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
    Field{"bounces", &ReferenceConfig::bounces, IntegerIn{1, 4096},
          {.doc = "path vertices: 1 direct only, 2 direct + one indirect bounce, n; in a `medium` each scattering event is a vertex too: light that has travelled a geometric path l has scattered about sigma_t l times, so set it above sigma_t x the axis's longest path + 4 sqrt of that (the light of longer chains is lost; core/reference/README.md, \"In a medium\")"}},
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

inline constexpr std::array<Name<RendererKind>, 2> kRendererNames{
    {{"ir", RendererKind::InstantRadiosity}, {"reference", RendererKind::Reference}}};
inline constexpr std::array<Name<IrBackendKind>, 3> kIrBackendNames{
    {{"auto", IrBackendKind::Auto}, {"gl", IrBackendKind::Gl}, {"cpu", IrBackendKind::Cpu}}};
inline constexpr std::array<Name<capture::MaterialModel>, 2> kMaterialNames{
    {{"lambertian", capture::MaterialModel::Lambertian}, {"gltf", capture::MaterialModel::Gltf}}};

// The keys of `render` (on RunConfig: some are the renderer's settings,
// RunConfig::render, others the run's); `indirect` and `reference` are
// sections of their own (kIndirectFields, kReferenceFields).
inline constexpr auto kRenderFields = std::tuple{
    Field{"renderer", &RunConfig::renderer, Choice<RendererKind>{kRendererNames},
          {.doc = "`ir` (instant radiosity) or `reference`"}},
    Field{"backend", &RunConfig::backend, Choice<IrBackendKind>{kIrBackendNames},
          {.doc = "device of `ir`: `gl` (OpenGL 4.5 through EGL: a GPU, or Mesa's llvmpipe), `cpu` (the native CPU backend, all cores, needs no EGL), or `auto`: `gl` when the EGL device platform offers a hardware GPU (llvmpipe/softpipe do not count), `cpu` otherwise. The choice is printed (`device: ...`) and recorded in `transient.json` (`backend`, `device`); `--backend` on `render` sets it. Both give the same volume within float rounding (tests/cpu)"}},
    Field{"threads", &RunConfig::cpu_threads, IntegerIn{0, 4096},
          {.doc = "worker threads of the `cpu` backend, and of the later bounces' ray tracing on both backends (0 = every core this process may run on: its CPU affinity, e.g. a Slurm task's `--cpus-per-task`, taskset or a container's cpuset); the bytes do not depend on it (tests/cpu, tests/ir BounceVplsTest)"}},
    In{"seed", &RunConfig::render, &capture::RenderSettings::seed, IntegerIn{0, 1LL << 62},
       {.doc = "seed of every random choice: the renderer's and the sensors'"}},
    In{"shadow_map_resolution", &RunConfig::render, &capture::RenderSettings::shadow_map_resolution, IntegerIn{16, 16384},
       {.unit = "pixel", .doc = "per cube face of the light's shadow map"}},
    In{"memory_budget", &RunConfig::render, &capture::RenderSettings::memory_budget_bytes, Bytes{0x1p20, 0x1p50},
       {.doc = "device memory (GPU, or RAM for `backend: cpu`) for volume segments and ISM batches; for `tofsim sense`, the host memory of the runs of pixels it reads from the saved files"}},
    Field{"strict", &RunConfig::strict, Flag{},
          {.doc = "light cut off by the time axis or a sensor window (more than 0.1 %) is an error, not a warning; `--strict` on `render` / `validate` sets it (see \"Time windows\")"}},
    In{"pixel_footprint", &RunConfig::render, &capture::RenderSettings::pixel_footprint, Flag{},
       {.doc = "a pixel integrates its area: every contribution is spread over the distribution of its optical path across the pixel (a trapezoid in time, first order; see README.md, \"Pixel footprints\"); `false`: all of a pixel's light in the bin of its centre's path (closed-form tests). `ir` only: the reference integrates by `reference.pixel_filter`"}},
    In{"pixel_samples", &RunConfig::render, &capture::RenderSettings::pixel_samples, IntegerIn{1, 16},
       {.doc = "N x N stratified surface samples per pixel, averaged (silhouettes, pixels that see two surfaces); each sample's footprint is its sub-pixel; costs N^2 gathers"}},
    In{"adaptive_pixel_samples", &RunConfig::render, &capture::RenderSettings::adaptive_pixel_samples, Flag{},
       {.doc = "with `pixel_samples` N > 1: the N x N samples only in pixels at an edge of the pixel-centre G-buffer (a 3 x 3 neighbour off the pixel's tangent plane by more than 5 degrees, a normal turned by more than 5 degrees, or surface next to background), or where the light reaches one of two neighbouring pixel centres and not the other (a shadow's edge or a hard spot's rim inside a flat pixel: a ray from each centre to the light, traced by the driver on either backend); every other pixel takes one sample at its centre with the whole pixel's footprint, exactly what `pixel_samples: 1` computes there (README.md, \"Pixel footprints\"). Silhouettes, creases and shadow edges at a fraction of N^2 the cost; texture edges inside a flat pixel are not detected. `ir` only"}},
    In{"materials", &RunConfig::render, &capture::RenderSettings::materials, Choice<capture::MaterialModel>{kMaterialNames},
       {.doc = "`lambertian`: every material reflects albedo / pi (base colour only; metallic and roughness ignored), the output of before, byte for byte. `gltf`: the glTF metallic-roughness BRDF (GGX, height-correlated Smith, Schlick; `metallicFactor`, `roughnessFactor`, `metallicRoughnessTexture`; README.md, \"Materials\") in the direct light seen by the camera, on both `ir` backends and in the reference, and in IR's indirect light: glossy VPLs (each records the direction its light came from and its material, and lights a point with its BRDF, clamped at `indirect.vpl_brdf_clamp`) and the BRDF on the camera side of every VPL contribution. The default stays `lambertian` because glTF's metallic 0, roughness 1 is not Lambertian: the shipped scenes would change"}},
    Custom{"indirect", "mapping", "", "defaults", "-", "indirect light (instant radiosity: VPLs), below"},
    Custom{"reference", "mapping", "", "defaults", "-", "the CPU path tracer's settings (`renderer: reference`), below"},
};
// clang-format on

}  // namespace tofsim::config
