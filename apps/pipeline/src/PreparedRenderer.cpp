#include "tofsim/pipeline/PreparedRenderer.h"

#include <system_error>

#include "tofsim/config/MaterialDelays.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

namespace {
std::size_t preparationsOf(const RendererChoice& choice) {
  const auto* ir = dynamic_cast<const ir::IrRenderer*>(choice.renderer.get());
  return ir ? ir->scenePreparations() : 0;
}
}  // namespace

PreparedRenderer::PreparedRenderer(gl::EglPlatform eglPlatform) : eglPlatform_(eglPlatform) {}

PreparedRenderer::~PreparedRenderer() = default;

PreparedRenderer::SceneKey PreparedRenderer::sceneKey(const fs::path& file) {
  // An unreadable file keeps size 0 and the epoch: loadGltf reports it.
  std::error_code ec;
  SceneKey key{fs::absolute(file, ec).lexically_normal(), 0, {}};
  key.size = fs::file_size(file, ec);
  if (ec) key.size = 0;
  key.modified = fs::last_write_time(file, ec);
  return key;
}

std::vector<std::optional<physics::ResponseKernel>> PreparedRenderer::delaysOf(
    const scene::Scene& scene) {
  std::vector<std::optional<physics::ResponseKernel>> delays;
  for (const scene::Material& m : scene.materials) delays.push_back(m.scatteringDelay);
  return delays;
}

bool PreparedRenderer::regionsDiffer(const config::RunConfig& config, const scene::Scene& scene) {
  if (config.render.media.size() != scene.regions.size()) return true;
  for (std::size_t i = 0; i < scene.regions.size(); ++i) {
    if (config.render.media[i].region != scene.regions[i].name) return true;
  }
  return false;
}

RendererSpec PreparedRenderer::specFor(const config::RunConfig& config) const {
  if (config.renderer == config::RendererKind::InstantRadiosity &&
      config.backend == config::IrBackendKind::Auto && !autoBackend_) {
    autoBackend_ = resolveIrBackend(config::IrBackendKind::Auto);
  }
  return rendererSpec(config, autoBackend_);
}

SetupChange PreparedRenderer::changeFor(const config::RunConfig& config) const {
  SetupChange change;
  if (!sceneKey_ || !(sceneKey(config.scene_file) == *sceneKey_)) {
    change.scene = true;
    change.what = sceneKey_ && sceneKey_->file == sceneKey(config.scene_file).file
                      ? "the scene file's contents (" + config.scene_file.string() + ")"
                      : "the scene (" + config.scene_file.string() + ")";
  } else if (regionsDiffer(config, *scene_)) {
    change.scene = true;
    change.what = "the media's regions (media:)";
  } else if (config::materialDelays(config, *scene_, report_.materialExtras) != delaysOf(*scene_)) {
    change.scene = true;
    change.what = "the materials' scattering delays (materials:)";
  }
  if (spec_) {
    const RendererSpec spec = specFor(config);
    const auto differs = [&](bool d, const char* what) {
      if (!d || change.renderer) return;
      change.renderer = true;
      if (change.what.empty()) change.what = what;
    };
    differs(spec.kind != spec_->kind, "render.renderer");
    differs(spec.backend != spec_->backend, "render.backend");
    differs(spec.cpuThreads != spec_->cpuThreads, "render.threads");
    differs(!(spec == *spec_), "render.reference");
  }
  return change;
}

SetupChange PreparedRenderer::prepare(const config::RunConfig& config) {
  const SetupChange change = changeFor(config);
  if (change.renderer) {
    earlierPreparations_ += preparationsOf(renderer_);
    renderer_ = {};
    spec_.reset();
  }
  // A region taken out of the scene's surfaces needs the file read again.
  const bool sameFile = sceneKey_ && sceneKey(config.scene_file) == *sceneKey_ &&
                        !regionsDiffer(config, *scene_);
  if (change.scene && sameFile) {
    // Only the delays changed: a copy with the new ones, not a reload.
    auto scene = std::make_unique<scene::Scene>(*scene_);
    config::applyMaterialDelays(config, *scene, report_.materialExtras);
    scene_ = std::move(scene);
    if (renderer_.renderer) renderer_.renderer->sceneChanged();
  } else if (change.scene) {
    scene::LoadReport report;
    auto scene = std::make_unique<scene::Scene>(loadConfiguredScene(config, &report));
    // A new object: a renderer kept across prepares it again at its next
    // render (IrRenderer compares the scene it holds by address).
    scene_ = std::move(scene);
    report_ = report;
    sceneKey_ = sceneKey(config.scene_file);
    ++sceneLoads_;
    if (renderer_.renderer) renderer_.renderer->sceneChanged();
  }
  // render.indirect.bounces may change with the scene kept.
  checkResponseClasses(config, *scene_);
  return change;
}

const scene::Scene& PreparedRenderer::scene() const {
  TOFSIM_CHECK(scene_ != nullptr);
  return *scene_;
}

const RendererChoice& PreparedRenderer::renderer(const config::RunConfig& config) {
  const RendererSpec spec = specFor(config);
  if (spec_ && !(spec == *spec_)) {
    earlierPreparations_ += preparationsOf(renderer_);
    renderer_ = {};
    spec_.reset();
  }
  if (!renderer_.renderer) {
    renderer_ = makeRenderer(spec, eglPlatform_);
    spec_ = spec;
    ++rendererMakes_;
  }
  return renderer_;
}

RendererChoice PreparedRenderer::makeAnother(const config::RunConfig& config) const {
  return makeRenderer(specFor(config), eglPlatform_);
}

std::size_t PreparedRenderer::scenePreparations() const {
  return earlierPreparations_ + preparationsOf(renderer_);
}

}  // namespace tofsim::pipeline
