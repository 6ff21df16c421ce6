#include "renderer/cloud_buffer.h"

#include <utility>

#include "renderer/gpu_interface.h"

namespace cloudsvc {

CloudBuffer::CloudBuffer() : uniforms_(gl::make_buffer(sizeof(TemporalUniforms), nullptr, GL_DYNAMIC_DRAW)) {}

void CloudBuffer::ensure_size(int w, int h, int divisor) {
  const glm::ivec2 c = cloud_buffer_size(w, h, divisor);
  if (fresh_radiance_ && c.x == w_ && c.y == h_) return;
  auto make = [&] { return gl::make_texture_2d(GL_RGBA32F, c.x, c.y, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE); };
  fresh_radiance_ = make();
  fresh_depth_ = make();
  for (int k = 0; k < 2; ++k) {
    radiance_[k] = make();
    depth_[k] = make();
  }
  w_ = c.x;
  h_ = c.y;
  prev_frame_.reset();
}

std::size_t CloudBuffer::gpu_bytes() const { return 6 * static_cast<std::size_t>(w_) * h_ * 16; }

TemporalPlan CloudBuffer::start_frame(const FrameContext& frame, const RenderQuality& quality) {
  const ViewRequest& view = frame.view;
  const bool history = prev_frame_ && history_usable(prev_frame_->view, prev_quality_, view, quality);
  std::optional<Reprojection> rep;
  if (history) rep = make_reprojection(*prev_frame_, frame);
  const bool fast = fast_motion_.update(rep && fast_cloud_motion(*rep, quality), history);
  const ViewRequest* prev = history ? &prev_frame_->view : nullptr;
  TemporalPlan plan = plan_temporal_frame(view, quality, history, prev, fast);
  still_frames_ = plan.camera_still ? still_frames_ + 1 : 0;
  plan.footprint_sample = footprint_sample_index(quality.temporal_reuse, view.frame_index, still_frames_, plan.stride);
  const TemporalUniforms tu = pack_temporal_uniforms(plan, quality, rep ? &*rep : nullptr, prev);
  glNamedBufferSubData(uniforms_.id(), 0, sizeof(TemporalUniforms), &tu);
  current_ = 1 - current_;
  prev_frame_ = frame;
  prev_frame_->view.reset_history = false;
  prev_quality_ = quality;
  return plan;
}

void CloudBuffer::clear_current() {
  // no in-scatter, transmittance 1; depth far, no layer
  const float empty_radiance[4] = {0.0f, 0.0f, 0.0f, 1.0f}, empty_depth[4] = {1e7f, 0.0f, -1.0f, 0.0f};
  glClearTexImage(radiance_[current_].id(), 0, GL_RGBA, GL_FLOAT, empty_radiance);
  glClearTexImage(depth_[current_].id(), 0, GL_RGBA, GL_FLOAT, empty_depth);
  prev_frame_.reset();
}

void CloudBuffer::take_fresh_as_current() {
  std::swap(fresh_radiance_, radiance_[current_]);
  std::swap(fresh_depth_, depth_[current_]);
}

void CloudBuffer::bind_uniforms() const { glBindBufferBase(GL_UNIFORM_BUFFER, gpu::ubo::TEMPORAL, uniforms_.id()); }

}  // namespace cloudsvc
