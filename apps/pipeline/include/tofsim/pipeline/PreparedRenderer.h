#pragma once
// A renderer that stays loaded: a scene loaded and a renderer made once, kept
// across the renders of many configs (tofsim.Renderer in Python, the runs of
// `tofsim batch` on one worker, the standalone render as a single use). What a
// config may change without a reload and what forces one is decided here, in
// changeFor(), and nowhere else:
//   - kept: the camera, the light, the time axis, the render settings, the
//     sensors and the outputs (each render's job is made from its config);
//   - the scene loaded again: another scene file, or the same file changed
//     on disk (its size or modification time); the scene copied with its
//     materials' new scattering delays when only `materials:` (or an axis
//     that changes how the extras read) changes them;
//   - the renderer made again: another render.renderer, render.backend (as
//     resolved, auto included), render.threads or render.reference.*.
// IR renderers prepare the scene (buffers, BVH) on their first render of it
// and keep it while it stays the same object (ir::IrRenderer).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::pipeline {

/// What rendering a config would load or make again, and why.
struct SetupChange {
  bool scene = false;     ///< the scene is loaded again
  bool renderer = false;  ///< the renderer is made again (and prepares the scene again)
  std::string what;       ///< the first thing that differs, e.g. "render.backend"; "" when none
  bool any() const { return scene || renderer; }
};

class PreparedRenderer {
 public:
  explicit PreparedRenderer(gl::EglPlatform eglPlatform = gl::EglPlatform::Auto);
  ~PreparedRenderer();
  PreparedRenderer(const PreparedRenderer&) = delete;
  PreparedRenderer& operator=(const PreparedRenderer&) = delete;

  /// What prepare(config) would do. Before the first prepare, everything.
  SetupChange changeFor(const config::RunConfig& config) const;
  /// Makes `config`'s scene current (loads it where changeFor says so) and
  /// drops a renderer whose settings differ (the next renderer() makes one).
  /// Returns what changed. Throws InputError for a scene that does not load.
  SetupChange prepare(const config::RunConfig& config);

  /// The scene of the last prepare(); its loader's report.
  const scene::Scene& scene() const;
  const scene::LoadReport& loadReport() const { return report_; }
  /// The renderer for the last prepare()'s config (or for `config`, with a
  /// scene the caller holds: runRender over a given scene), made on first
  /// use: a bad output folder or a plan that does not fit fails before a
  /// device is opened.
  const RendererChoice& renderer(const config::RunConfig& config);
  /// A fresh renderer like renderer(config)'s, not kept here: a capture
  /// loop's further workers (CaptureLoop.h).
  RendererChoice makeAnother(const config::RunConfig& config) const;
  /// The spec of renderer(config)'s renderer (render.backend: auto decided once).
  RendererSpec specFor(const config::RunConfig& config) const;

  /// Counts for logs and tests: scenes loaded, renderers made, and the
  /// scene preparations of the IR renderers made so far (0 for the reference).
  std::size_t sceneLoads() const { return sceneLoads_; }
  std::size_t rendererMakes() const { return rendererMakes_; }
  std::size_t scenePreparations() const;

 private:
  struct SceneKey {
    std::filesystem::path file;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type modified;
    bool operator==(const SceneKey&) const = default;
  };
  static SceneKey sceneKey(const std::filesystem::path& file);
  /// Whether config's `media:` regions are not the ones taken out of `scene`.
  static bool regionsDiffer(const config::RunConfig& config, const scene::Scene& scene);
  static std::vector<std::optional<physics::ResponseKernel>> delaysOf(const scene::Scene& scene);

  gl::EglPlatform eglPlatform_;
  /// render.backend: auto, decided once (it asks EGL for a hardware GPU).
  mutable std::optional<config::IrBackendKind> autoBackend_;
  std::optional<SceneKey> sceneKey_;
  std::unique_ptr<scene::Scene> scene_;
  scene::LoadReport report_;
  std::optional<RendererSpec> spec_;
  RendererChoice renderer_;
  std::size_t sceneLoads_ = 0;
  std::size_t rendererMakes_ = 0;
  std::size_t earlierPreparations_ = 0;  ///< of renderers dropped
};

}  // namespace tofsim::pipeline
