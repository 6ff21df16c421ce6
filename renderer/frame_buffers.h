// The per-frame GPU buffers every pass reads: the frame uniforms (renderer/frame_uniforms.h)
// and the frame counters (shaders/frame_counters.glsl). A pass binds them with bind()
// before its dispatch. Needs a current GL 4.5 context.
#pragma once

#include <cstdint>

#include "renderer/frame_uniforms.h"
#include "renderer/gl/gl_objects.h"

namespace cloudsvc {

// Counters the passes add to (std430 block FrameCounters).
struct FrameCounters {
  std::uint32_t density_evals = 0;     // cloud density evaluations (when counted)
  std::uint32_t nonfinite_pixels = 0;  // pixels the composite zeroed (NaN, Inf, negative)
  std::uint32_t cloud_pixels = 0;      // pixels with cloud opacity > kCloudPixelOpacity
  std::uint32_t loop_capped_invocations = 0;  // invocations the driver's loop cap cut short (count_if_loops_capped)
};

class FrameBuffers {
 public:
  FrameBuffers();
  // Uploads this frame's uniforms and zeroes the counters.
  void start_frame(const FrameUniforms& u);
  // Binds the uniforms at gpu::ubo::FRAME and the counters at gpu::ssbo::FRAME_COUNTERS.
  void bind() const;
  // Reads the counters back (waits for the passes that add to them).
  FrameCounters read_counters() const;

 private:
  gl::Buffer uniforms_, counters_;
};

}  // namespace cloudsvc
