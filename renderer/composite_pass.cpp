#include "renderer/composite_pass.h"

#include "renderer/gl/compute_dispatch.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {

CompositePass::CompositePass() : program_(gl::ShaderProgram::compute("composite.comp")) {}

void CompositePass::ensure_size(int w, int h) {
  if (target_ && w == w_ && h == h_) return;
  target_ = gl::make_texture_2d(GL_RGBA32F, w, h, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  w_ = w;
  h_ = h;
}

void CompositePass::run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer,
                        bool shadows_per_pixel) {
  if (shadows_per_pixel)
    inputs.use(per_pixel_programs_);  // marches the density: its variant for the frame
  else
    program_.use();
  inputs.bind();
  buffer.bind_uniforms();
  shadows.bind_lookups();
  glBindTextureUnit(gpu::tex::CLOUD_RADIANCE, buffer.current_radiance().id());
  glBindTextureUnit(gpu::tex::CLOUD_DEPTH, buffer.current_depth().id());
  glBindImageTexture(gpu::img::FRAME_OUT, target_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl::dispatch_2d(w_, h_);
}

void CompositePass::read_back(FrameImage& img) const {
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  img.width = w_;
  img.height = h_;
  img.rgba.resize(static_cast<size_t>(w_) * h_ * 4);
  glGetTextureImage(target_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(img.rgba.size() * sizeof(float)),
                    img.rgba.data());
}

}  // namespace cloudsvc
