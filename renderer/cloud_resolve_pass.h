// The temporal resolve pass (shaders/cloud_resolve.comp): combines this frame's fresh
// samples with the previous resolved buffer, reprojected, into this frame's resolved
// buffer. Binds what it reads: the frame buffers, the temporal uniforms, the fresh and
// history textures. Needs a current GL 4.5 context.
#pragma once

#include "renderer/cloud_buffer.h"
#include "renderer/frame_buffers.h"
#include "renderer/gl/shader_program.h"

namespace cloudsvc {

class CloudResolvePass {
 public:
  CloudResolvePass();
  void run(const FrameBuffers& frame, const CloudBuffer& buffer) const;

 private:
  gl::ShaderProgram program_;
};

}  // namespace cloudsvc
