#pragma once
// A CPU transient path tracer: the ground truth the GL renderer is measured
// against. Same job, result and segment stream as the IR renderer (ir::IrRenderer).
//
// Estimator (see core/reference/README.md):
//  - pixel_filter box (default): each path starts at a stratified sub-pixel
//    point, so a pixel integrates its area; point: one primary ray through each
//    pixel centre, as the GL G-buffer;
//  - bounce 1 (direct light) evaluated exactly with a shadow ray at each primary
//    hit (with point: no noise), the
//    same formula and time binning as the GL direct gather. Goes to Segment::direct,
//    with the light seen straight by the camera (capture::DirectLightView);
//  - bounces 2..n: samples_per_pixel continuations of fixed depth, cosine-sampled
//    (with render.materials: gltf, drawn from the cosine + GGX VNDF mixture)
//    (no Russian roulette), next-event estimation towards the light at every
//    vertex, each contribution binned at its full optical path. Segment::indirect.
//  - a material's scattering delay (scene::Material::scatteringDelay): at each
//    vertex of such a material the light is delayed with probability
//    `fraction` by a delay drawn from the kernel and re-emitted through its
//    matrix (a delay per vertex, Jarabo et al. 2014), from a random stream of
//    its own; energy is kept path by path.
//  - in a medium (RenderSettings::medium present; src/MediumPaths.cpp):
//    every vertex a surface or a medium event (free flights by spectral MIS
//    over the channels' sigma_t, phase sampling), next-event estimation
//    through the medium, the medium's light along each leg also by
//    equiangular points (Equiangular.h); a medium event counts as a bounce.
//    Without one the paths above run unchanged (the same bytes).
// Deterministic: every pixel draws from its own generator seeded with
// (RenderSettings::seed, pixel index), so the bytes depend neither on the
// thread count nor on scheduling.
// Any capture::Imager: a pinhole camera, or a point set (the relay-wall points
// of an NLOS scan: primary rays from its origin, the last leg timed or not by
// capture::lastLegCounts; points without extent take the point filter).

#include <cstdint>
#include <memory>

#include "tofsim/capture/Renderer.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::reference {

using rays::RayScene;

/// What a pixel integrates: its whole area (box) or the ray through its centre
/// (point, the G-buffer's view: kept for closed-form tests at pixel centres).
enum class PixelFilter { Box, Point };

/// How a path continues at a surface with render.materials: gltf (Lambertian
/// surfaces are always cosine-sampled): BrdfMixture draws from the one-sample
/// MIS mixture of the cosine lobe and GGX visible normals
/// (tofsim/physics/GltfSampling.h); Cosine keeps cosine sampling weighted by
/// pi f (for variance comparisons; the bytes of the renderer before the mixture).
enum class ContinuationSampling { BrdfMixture, Cosine };

struct ReferenceSettings {
  /// Surface interactions per path: 1 = direct only, 2 = direct + one indirect
  /// bounce (the paper's), n = up to n - 1 indirect bounces. >= 1.
  int32_t bounces = 2;
  /// Indirect paths per pixel; the direct term needs none. >= 1.
  int32_t samples_per_pixel = 64;
  /// Box: every path starts at its own stratified, jittered sub-pixel point, and
  /// the direct term is averaged over those points too. Point: one ray through
  /// the pixel centre, the direct term exact there.
  PixelFilter pixel_filter = PixelFilter::Box;
  /// Worker threads; 0 = std::thread::hardware_concurrency().
  int32_t threads = 0;
  /// Direction sampling of glTF surfaces (render.reference.sampling).
  ContinuationSampling sampling = ContinuationSampling::BrdfMixture;
};

class ReferenceRenderer : public capture::Renderer {
 public:
  explicit ReferenceRenderer(ReferenceSettings settings);

  /// "CPU reference path tracer".
  std::string description() const override;

  /// Renders the job and streams the volume to `sink` in row-aligned segments,
  /// in order. RenderSettings::indirect.enabled = false renders bounce 1 only;
  /// the other IndirectSettings (VPLs, ISMs) and shadow_map_resolution do not
  /// apply. memory_budget_bytes bounds the host buffers of one segment.
  /// Segments go through the shared segment loop (capture::streamSegments).
  /// Throws InputError for invalid settings. Not thread-safe: the scene's
  /// BVH is built when job.scene is not the last render's scene and kept, so
  /// a sequence of captures of one scene (an NLOS scan's laser positions)
  /// builds it once.
  capture::RenderResult render(const capture::RenderJob& job, capture::SegmentSink& sink,
                               const capture::ProgressCallback& progress = {}) const override;
  /// The held scene was changed in place: the next render builds it again.
  void sceneChanged() const override;
  /// How many times a scene's BVH was built (for tests and statistics).
  std::size_t scenePreparations() const { return scenePreparations_; }

  const ReferenceSettings& settings() const { return settings_; }

 private:
  const RayScene& rays(const scene::Scene& scene, int32_t threads) const;

  ReferenceSettings settings_;
  // The prepared scene; mutable because render is const (Renderer's interface).
  mutable const scene::Scene* scene_ = nullptr;
  mutable std::unique_ptr<RayScene> rays_;
  mutable std::size_t scenePreparations_ = 0;
};

}  // namespace tofsim::reference
