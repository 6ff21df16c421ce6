// The cloud buffer (shaders/temporal_uniforms.glsl): per cloud pixel, the clouds along its
// ray, at 1/divisor of the frame per axis. Holds this frame's fresh samples (written by the
// march) and the resolved buffers of the previous and the current frame (ping-pong,
// written by the resolve), the temporal uniforms, and what temporal reuse remembers of the
// last frame (renderer/temporal_reprojection.h). Radiance textures hold in-scattered
// radiance (rgb) and transmittance (a); depth textures the cloud depth (m), the clouds'
// shift of the ground's share of the background (shaders/cloud_march.comp), the depth's layer
// and the history length. Needs a current GL 4.5 context.
#pragma once

#include <optional>

#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"
#include "renderer/frame_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/temporal_reprojection.h"
#include "renderer/temporal_uniforms.h"
#include "weather/wind_drift.h"

namespace cloudsvc {

class CloudBuffer {
 public:
  CloudBuffer();

  // Sizes the buffer for a frame of w x h pixels; a new size drops the history.
  void ensure_size(int w, int h, int divisor);
  int width() const { return w_; }
  int height() const { return h_; }

  // Decides this frame's temporal plan (history usable, stride, offset), uploads the
  // temporal uniforms, and makes the other resolved buffer the one this frame writes.
  TemporalPlan start_frame(const FrameContext& frame, const RenderQuality& quality);
  // This frame marches nothing: its resolved buffer holds no cloud, and the next frame
  // starts a new history.
  void clear_current();
  // Every pixel marched, no history: the fresh samples become this frame's resolved buffer
  // (what the resolve would copy).
  void take_fresh_as_current();
  void reset_history() { prev_frame_.reset(); }

  // Binds the temporal uniforms at gpu::ubo::TEMPORAL.
  void bind_uniforms() const;

  const gl::Texture& fresh_radiance() const { return fresh_radiance_; }
  const gl::Texture& fresh_depth() const { return fresh_depth_; }
  const gl::Texture& history_radiance() const { return radiance_[1 - current_]; }
  const gl::Texture& history_depth() const { return depth_[1 - current_]; }
  const gl::Texture& current_radiance() const { return radiance_[current_]; }
  const gl::Texture& current_depth() const { return depth_[current_]; }
  std::size_t gpu_bytes() const;

 private:
  gl::Texture fresh_radiance_, fresh_depth_, radiance_[2], depth_[2];
  int current_ = 0;  // index of this frame's resolved buffer
  int w_ = 0, h_ = 0;
  gl::Buffer uniforms_;
  std::optional<FrameContext> prev_frame_;  // the last frame, while its buffer may be reused
  RenderQuality prev_quality_;
  int still_frames_ = 0;        // consecutive still-camera frames, the last one included
  FastMotionHold fast_motion_;  // 1/4 px instead of 1/16 while the clouds move fast
};

}  // namespace cloudsvc
