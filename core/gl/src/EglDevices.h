#pragma once
// EGL device enumeration (EGL_EXT_device_enumeration), shared by the context
// (which opens a display on the first hardware device) and by the probe that
// decides render.backend: auto without creating any context.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>
#include <vector>

namespace tofsim::gl::detail {

/// Whether the space-separated extension `list` holds `token` (null: no).
bool hasToken(const char* list, const char* token);

template <typename Fn>
Fn eglProc(const char* name) {
  return reinterpret_cast<Fn>(eglGetProcAddress(name));
}

struct HardwareDevices {
  std::vector<EGLDeviceEXT> devices;  ///< in enumeration order; software ones left out
  std::string why;                    ///< why there are none, when empty
};

/// The EGL devices that are not software rasterizers (llvmpipe, softpipe).
/// Never throws: no EGL, no extension or no device gives an empty list.
HardwareDevices hardwareEglDevices(const char* clientExtensions);

/// The device's renderer name (EGL_EXT_device_query_name), else its DRM node,
/// else "EGL device".
std::string eglDeviceName(EGLDeviceEXT device);

}  // namespace tofsim::gl::detail
