#include "tofsim/gl/Context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "EglDevices.h"
#include "tofsim/gl/GL.h"
#include "tofsim/util/Error.h"

namespace tofsim::gl {

EglPlatform parseEglPlatform(const std::string& name) {
  if (name == "auto") return EglPlatform::Auto;
  if (name == "surfaceless") return EglPlatform::Surfaceless;
  if (name == "device") return EglPlatform::Device;
  throw InputError("unknown EGL platform '" + name + "' (use auto, surfaceless or device)");
}

EglPlatform eglPlatformFromEnvironment() {
  const char* value = std::getenv("TOFSIM_EGL_PLATFORM");
  if (!value || !*value) return EglPlatform::Auto;
  try {
    return parseEglPlatform(value);
  } catch (const InputError& e) {
    throw InputError(std::string("TOFSIM_EGL_PLATFORM: ") + e.what());
  }
}

namespace {

using detail::eglProc;
using detail::hasToken;

// A display on the first EGL device that is not a software rasterizer, or
// EGL_NO_DISPLAY.
EGLDisplay openDeviceDisplay(const char* clientExtensions, std::string& why) {
  const detail::HardwareDevices hardware = detail::hardwareEglDevices(clientExtensions);
  auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (hardware.devices.empty() || !getPlatformDisplay) {
    why = hardware.why.empty() ? "eglGetPlatformDisplayEXT is missing" : hardware.why;
    return EGL_NO_DISPLAY;
  }
  for (EGLDeviceEXT device : hardware.devices) {
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display != EGL_NO_DISPLAY) return display;
  }
  why = "no display could be opened on a hardware EGL device";
  return EGL_NO_DISPLAY;
}

EGLDisplay openSurfacelessDisplay(const char* clientExtensions, std::string& why) {
  if (!hasToken(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    why = "EGL client extension EGL_MESA_platform_surfaceless is missing (install libegl-mesa0)";
    return EGL_NO_DISPLAY;
  }
  auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLDisplay d = getPlatformDisplay ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA,
                                                         EGL_DEFAULT_DISPLAY, nullptr)
                                    : EGL_NO_DISPLAY;
  if (d == EGL_NO_DISPLAY) why = "eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA) failed";
  return d;
}

std::string eglErrorText() {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "EGL error 0x%04x", eglGetError());
  return buffer;
}

// Terminates an initialized display on every failure path after
// eglInitialize; the Context takes it with release() once it is complete.
class InitializedDisplay {
 public:
  explicit InitializedDisplay(EGLDisplay display) : display_(display) {}
  ~InitializedDisplay() {
    if (display_ != EGL_NO_DISPLAY) eglTerminate(display_);
  }
  InitializedDisplay(const InitializedDisplay&) = delete;
  InitializedDisplay& operator=(const InitializedDisplay&) = delete;
  EGLDisplay release() {
    EGLDisplay d = display_;
    display_ = EGL_NO_DISPLAY;
    return d;
  }

 private:
  EGLDisplay display_;
};

// A current OpenGL 4.5 core context on an initialized display.
EGLContext makeCurrentContext(EGLDisplay display, const std::string& platformName) {
  if (!eglBindAPI(EGL_OPENGL_API)) throw InputError("eglBindAPI(EGL_OPENGL_API) failed");
  const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  const bool noConfig =
      hasToken(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
  if (!noConfig &&
      (!eglChooseConfig(display, configAttribs, &config, 1, &configCount) || configCount == 0)) {
    throw InputError("no EGL config supports desktop OpenGL on the " + platformName + " platform");
  }
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   4,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   5,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_NONE};
  EGLContext context = eglCreateContext(display, noConfig ? EGL_NO_CONFIG_KHR : config,
                                        EGL_NO_CONTEXT, contextAttribs);
  if (context == EGL_NO_CONTEXT) {
    throw InputError("the " + platformName +
                     " EGL platform cannot create an OpenGL 4.5 core context (" + eglErrorText() +
                     ")");
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    const std::string err = eglErrorText();
    eglDestroyContext(display, context);
    throw InputError("eglMakeCurrent without a surface failed (" + err +
                     "; EGL_KHR_surfaceless_context is required)");
  }
  return context;
}

}  // namespace

Context::Context(EglPlatform platform) {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!clientExtensions) {
    throw InputError(
        "no EGL client extensions: libEGL is missing or has no vendor library "
        "(install libegl1 and libegl-mesa0, or the GPU driver's EGL)");
  }
  std::string whyDevice, whySurfaceless, platformName;
  EGLDisplay display = EGL_NO_DISPLAY;
  if (platform != EglPlatform::Surfaceless) {
    display = openDeviceDisplay(clientExtensions, whyDevice);
    platformName = "device";
  }
  if (display == EGL_NO_DISPLAY && platform != EglPlatform::Device) {
    display = openSurfacelessDisplay(clientExtensions, whySurfaceless);
    platformName = "surfaceless";
  }
  if (display == EGL_NO_DISPLAY) {
    std::string why = "cannot create a headless OpenGL context: ";
    if (!whyDevice.empty()) why += "device platform: " + whyDevice;
    if (!whySurfaceless.empty()) {
      why += std::string(whyDevice.empty() ? "" : "; ") + "surfaceless platform: " + whySurfaceless;
    }
    throw InputError(why);
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    throw InputError("eglInitialize failed on the " + platformName +
                     " platform: " + eglErrorText());
  }
  InitializedDisplay initialized(display);
  context_ = makeCurrentContext(display, platformName);
  display_ = initialized.release();

  GLint64 ssbo = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &ssbo);
  limits_.maxShaderStorageBlockBytes = static_cast<std::size_t>(ssbo);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limits_.maxTextureSize);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &limits_.max3DTextureSize);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &limits_.maxArrayTextureLayers);
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &limits_.maxComputeSharedMemoryBytes);
  for (GLuint i = 0; i < 3; ++i) {
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &limits_.maxComputeWorkGroupCount[i]);
  }
  const auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  description_ = str(GL_RENDERER) + " / OpenGL " + str(GL_VERSION) + " / EGL " + platformName;
}

Context::~Context() {
  if (display_) {
    auto display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
  }
}

bool Context::hasExtension(const std::string& name) const {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* ext =
        reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (ext && name == ext) return true;
  }
  return false;
}

std::optional<std::string> hardwareGpuName() {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!clientExtensions) return std::nullopt;  // no EGL client extensions at all
  const detail::HardwareDevices hardware = detail::hardwareEglDevices(clientExtensions);
  if (hardware.devices.empty()) return std::nullopt;
  return detail::eglDeviceName(hardware.devices.front());
}

}  // namespace tofsim::gl
