#include "renderer/gl/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstring>
#include <stdexcept>
#include <vector>

namespace cloudsvc::gl {

namespace {

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#ifndef EGL_PLATFORM_DEVICE_EXT
#define EGL_PLATFORM_DEVICE_EXT 0x313F
#endif

using GetPlatformDisplayFn = EGLDisplay (*)(EGLenum, void*, const EGLint*);
using QueryDevicesFn = EGLBoolean (*)(EGLint, void**, EGLint*);

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

// libepoxy aborts on eglGetPlatformDisplay before a display exists: fetch the EXT entry
// point directly (libepoxy 1.5.10 aborts with "No provider of eglGetPlatformDisplay found";
// docs/ARCHITECTURE.md, "Threads and contexts").
GetPlatformDisplayFn platform_display_fn() {
  return reinterpret_cast<GetPlatformDisplayFn>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
}

EGLDisplay try_initialize(EGLDisplay dpy) {
  if (dpy == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) return EGL_NO_DISPLAY;
  return dpy;
}

}  // namespace

struct EglContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string platform;
};

EglContext::EglContext() : impl_(std::make_unique<Impl>()) {
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  GetPlatformDisplayFn get_display = platform_display_fn();
  if (!get_display) {
    throw std::runtime_error(
        "EGL: eglGetPlatformDisplayEXT is unavailable (need libegl1 with EGL_EXT_platform_base; "
        "install libegl-mesa0 libgl1-mesa-dri)");
  }
  if (has_extension(client_ext, "EGL_MESA_platform_surfaceless")) {
    impl_->display = try_initialize(get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    if (impl_->display != EGL_NO_DISPLAY) impl_->platform = "surfaceless";
  }
  if (impl_->display == EGL_NO_DISPLAY && has_extension(client_ext, "EGL_EXT_platform_device")) {
    auto query = reinterpret_cast<QueryDevicesFn>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLint count = 0;
    if (query && query(0, nullptr, &count) && count > 0) {
      std::vector<void*> devices(static_cast<size_t>(count));
      query(count, devices.data(), &count);
      for (EGLint i = 0; i < count && impl_->display == EGL_NO_DISPLAY; ++i) {
        impl_->display = try_initialize(get_display(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(i)], nullptr));
        if (impl_->display != EGL_NO_DISPLAY) impl_->platform = "device";
      }
    }
  }
  if (impl_->display == EGL_NO_DISPLAY) {
    throw std::runtime_error(
        "EGL: no headless display (neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device "
        "could be initialised); install Mesa's EGL driver: apt-get install libegl-mesa0 libgl1-mesa-dri");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: eglBindAPI(EGL_OPENGL_API) failed");

  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  // Surfaceless contexts need no config (EGL_KHR_no_config_context).
  impl_->context = eglCreateContext(impl_->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (impl_->context == EGL_NO_CONTEXT) {
    eglTerminate(impl_->display);
    throw std::runtime_error("EGL: cannot create an OpenGL 4.5 core context (driver supports less than 4.5?)");
  }
  if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context)) {
    eglDestroyContext(impl_->display, impl_->context);
    eglTerminate(impl_->display);
    throw std::runtime_error("EGL: eglMakeCurrent without surface failed (EGL_KHR_surfaceless_context missing)");
  }
}

EglContext::~EglContext() {
  if (impl_->display != EGL_NO_DISPLAY) {
    eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
    eglTerminate(impl_->display);
  }
}

std::string EglContext::description() const {
  const char* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return std::string(r ? r : "unknown renderer") + " (" + impl_->platform + ")";
}

}  // namespace cloudsvc::gl
