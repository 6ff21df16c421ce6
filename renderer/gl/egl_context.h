// Headless OpenGL 4.5 core context through EGL (no window, no display server).
// Tries the surfaceless platform (EGL_MESA_platform_surfaceless), then the device
// platform (EGL_EXT_platform_device). On a machine without a GPU this is Mesa llvmpipe;
// with a GPU, the vendor driver. See docs/ARCHITECTURE.md, "Threads and contexts".
#pragma once

#include <memory>
#include <string>

namespace cloudsvc::gl {

class EglContext {
 public:
  // Creates the context and makes it current on the calling thread. Throws
  // std::runtime_error with a message that says what is missing when it cannot.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // "GL_RENDERER string (platform)", e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (surfaceless)".
  std::string description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cloudsvc::gl
