#include "renderer/gl/pass_timer.h"

#include <epoxy/gl.h>

namespace cloudsvc::gl {

void PassTimer::begin(int pass) {
  pass_ = pass;
  start_ = std::chrono::steady_clock::now();
}

void PassTimer::end() {
  glFinish();
  ms_[static_cast<size_t>(pass_)] += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace cloudsvc::gl
