#include "renderer/cloud_march_pass.h"

#include "renderer/gl/compute_dispatch.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {

void CloudMarchPass::run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer, const TemporalPlan& plan) const {
  inputs.use(programs_);
  inputs.bind();
  shadows.bind_lookups();
  buffer.bind_uniforms();
  glBindImageTexture(gpu::img::FRESH_RADIANCE_OUT, buffer.fresh_radiance().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  glBindImageTexture(gpu::img::FRESH_DEPTH_OUT, buffer.fresh_depth().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl::dispatch_2d((buffer.width() + plan.stride - 1) / plan.stride, (buffer.height() + plan.stride - 1) / plan.stride);
}

}  // namespace cloudsvc
