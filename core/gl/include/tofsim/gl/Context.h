#pragma once
// The one headless OpenGL 4.5 core context class, made through EGL without any
// window system:
//  - surfaceless: Mesa's EGL_MESA_platform_surfaceless (llvmpipe on machines
//    without a GPU, or Mesa's hardware drivers);
//  - device: EGL_EXT_platform_device on an enumerated GPU (NVIDIA's driver).
// `auto` picks the first hardware EGL device and falls back to surfaceless.
// The choice comes from the constructor or the TOFSIM_EGL_PLATFORM environment
// variable (auto | surfaceless | device).

#include <cstddef>
#include <optional>
#include <string>

namespace tofsim::gl {

enum class EglPlatform { Auto, Surfaceless, Device };

/// Parses "auto", "surfaceless" or "device"; throws InputError otherwise.
EglPlatform parseEglPlatform(const std::string& name);
/// The platform named by TOFSIM_EGL_PLATFORM, or Auto when unset.
EglPlatform eglPlatformFromEnvironment();

/// The name of the first hardware GPU the EGL device platform offers (what
/// `auto` would open; software devices such as llvmpipe do not count), or
/// nullopt. Creates no context and never throws: no EGL, no device extension
/// or no device all give nullopt. Decides render.backend: auto.
std::optional<std::string> hardwareGpuName();

/// Implementation limits queried once the context exists; batching and
/// segmenting are planned around them.
struct ContextLimits {
  std::size_t maxShaderStorageBlockBytes = 0;
  int maxTextureSize = 0;
  int max3DTextureSize = 0;
  int maxArrayTextureLayers = 0;
  int maxComputeSharedMemoryBytes = 0;
  int maxComputeWorkGroupCount[3] = {0, 0, 0};
};

class Context {
 public:
  explicit Context(EglPlatform platform = eglPlatformFromEnvironment());
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const ContextLimits& limits() const { return limits_; }
  /// e.g. "llvmpipe (LLVM 15.0.6, 256 bits) / OpenGL 4.5 (Core Profile) Mesa 22.3.6 / surfaceless"
  const std::string& description() const { return description_; }
  bool hasExtension(const std::string& name) const;

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  ContextLimits limits_;
  std::string description_;
};

}  // namespace tofsim::gl
