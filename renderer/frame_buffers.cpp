#include "renderer/frame_buffers.h"

#include "renderer/gpu_interface.h"

namespace cloudsvc {

FrameBuffers::FrameBuffers()
    : uniforms_(gl::make_buffer(sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW)),
      counters_(gl::make_buffer(sizeof(FrameCounters), nullptr, GL_DYNAMIC_READ)) {}

void FrameBuffers::start_frame(const FrameUniforms& u) {
  glNamedBufferSubData(uniforms_.id(), 0, sizeof(FrameUniforms), &u);
  const FrameCounters zero{};
  glNamedBufferSubData(counters_.id(), 0, sizeof(FrameCounters), &zero);
}

void FrameBuffers::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, gpu::ubo::FRAME, uniforms_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::FRAME_COUNTERS, counters_.id());
}

FrameCounters FrameBuffers::read_counters() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  FrameCounters c{};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof(FrameCounters), &c);
  return c;
}

}  // namespace cloudsvc
