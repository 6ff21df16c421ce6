// Wall-clock time of a frame's passes: each end() waits for the GL (glFinish) and reads a
// steady clock. On llvmpipe, where a compute dispatch runs on the CPU, this costs nothing
// measurable (its GL_TIME_ELAPSED queries report 0 for compute); on a GPU it serialises
// the passes, which is acceptable for a renderer that reads every frame back anyway.
#pragma once

#include <array>
#include <chrono>

namespace cloudsvc::gl {

class PassTimer {
 public:
  static constexpr int kMaxPasses = 8;

  void begin(int pass);  // pass in [0, kMaxPasses); passes may not nest
  void end();
  double ms(int pass) const { return ms_[static_cast<size_t>(pass)]; }  // 0 if not timed
  void reset() { ms_.fill(0.0); }

 private:
  std::array<double, kMaxPasses> ms_{};
  int pass_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace cloudsvc::gl
