#include "renderer/cloud_resolve_pass.h"

#include "renderer/gl/compute_dispatch.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {

CloudResolvePass::CloudResolvePass() : program_(gl::ShaderProgram::compute("cloud_resolve.comp")) {}

void CloudResolvePass::run(const FrameBuffers& frame, const CloudBuffer& buffer) const {
  program_.use();
  frame.bind();
  buffer.bind_uniforms();
  glBindTextureUnit(gpu::tex::FRESH_RADIANCE, buffer.fresh_radiance().id());
  glBindTextureUnit(gpu::tex::FRESH_DEPTH, buffer.fresh_depth().id());
  glBindTextureUnit(gpu::tex::HISTORY_RADIANCE, buffer.history_radiance().id());
  glBindTextureUnit(gpu::tex::HISTORY_DEPTH, buffer.history_depth().id());
  glBindImageTexture(gpu::img::CLOUD_RADIANCE_OUT, buffer.current_radiance().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  glBindImageTexture(gpu::img::CLOUD_DEPTH_OUT, buffer.current_depth().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  gl::dispatch_2d(buffer.width(), buffer.height());
}

}  // namespace cloudsvc
