#include "renderer/composite_pass.h"

#include "renderer/gl/compute_dispatch.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {

CompositePass::CompositePass() : program_(gl::ShaderProgram::compute("composite.comp")) {}

void CompositePass::run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer,
                        const FrameTarget& target, bool shadows_per_pixel) {
  if (shadows_per_pixel)
    inputs.use(per_pixel_programs_);  // marches the density: its variant for the frame
  else
    program_.use();
  inputs.bind();
  buffer.bind_uniforms();
  shadows.bind_lookups();
  glBindTextureUnit(gpu::tex::CLOUD_RADIANCE, buffer.current_radiance().id());
  glBindTextureUnit(gpu::tex::CLOUD_DEPTH, buffer.current_depth().id());
  glBindImageTexture(gpu::img::FRAME_OUT, target.texture().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl::dispatch_2d(target.width(), target.height());
}

}  // namespace cloudsvc
