#include "EglDevices.h"

#include <cstring>

// EGL_EXT_device_query_name; older headers lack it.
#ifndef EGL_RENDERER_EXT
#define EGL_RENDERER_EXT 0x335F
#endif

namespace tofsim::gl::detail {

bool hasToken(const char* list, const char* token) {
  if (!list) return false;
  const std::size_t n = std::strlen(token);
  for (const char* p = std::strstr(list, token); p; p = std::strstr(p + 1, token)) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

namespace {

const char* deviceString(EGLDeviceEXT device, EGLint name) {
  auto query = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  return query ? query(device, name) : nullptr;
}

// Mesa marks its software devices with an extension; the renderer name
// catches drivers that do not.
bool isSoftware(EGLDeviceEXT device) {
  if (hasToken(deviceString(device, EGL_EXTENSIONS), "EGL_MESA_device_software")) return true;
  const std::string name = eglDeviceName(device);
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

}  // namespace

std::string eglDeviceName(EGLDeviceEXT device) {
  if (hasToken(deviceString(device, EGL_EXTENSIONS), "EGL_EXT_device_query_name")) {
    if (const char* renderer = deviceString(device, EGL_RENDERER_EXT)) return renderer;
  }
  if (const char* node = deviceString(device, EGL_DRM_DEVICE_FILE_EXT)) return node;
  return "EGL device";
}

HardwareDevices hardwareEglDevices(const char* clientExtensions) {
  HardwareDevices out;
  if (!hasToken(clientExtensions, "EGL_EXT_platform_device") ||
      !(hasToken(clientExtensions, "EGL_EXT_device_enumeration") ||
        hasToken(clientExtensions, "EGL_EXT_device_base"))) {
    out.why =
        "EGL client extensions EGL_EXT_platform_device and EGL_EXT_device_enumeration are missing";
    return out;
  }
  auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  EGLint count = 0;
  if (!queryDevices || !queryDevices(0, nullptr, &count) || count == 0) {
    out.why = "no EGL device was enumerated (is the GPU driver's EGL vendor library installed?)";
    return out;
  }
  std::vector<EGLDeviceEXT> all(static_cast<std::size_t>(count));
  queryDevices(count, all.data(), &count);
  all.resize(static_cast<std::size_t>(count));
  for (EGLDeviceEXT device : all) {
    if (!isSoftware(device)) out.devices.push_back(device);
  }
  if (out.devices.empty()) out.why = "only software EGL devices were found";
  return out;
}

}  // namespace tofsim::gl::detail
