// The cloud march pass (shaders/cloud_march.comp): marches this frame's fresh cloud pixels
// (one in stride x stride, TemporalPlan) through the layer intervals and writes their
// radiance, transmittance and depth into the cloud buffer's fresh textures. Binds
// everything it reads: the frame buffers, the cloud field, the atmosphere lookups, the
// ground shadow map and light volume, the temporal uniforms. Needs a current GL context.
#pragma once

#include "renderer/cloud_buffer.h"
#include "renderer/cloud_pass_inputs.h"
#include "renderer/gl/shader_program.h"
#include "renderer/ground_shadow_map.h"

namespace cloudsvc {

class CloudMarchPass {
 public:
  // density_defines: the cloud density's variant (cloud_density_defines, cloud_field_textures.h)
  explicit CloudMarchPass(const std::vector<std::string>& density_defines = {});
  void run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer, const TemporalPlan& plan) const;

 private:
  gl::ShaderProgram program_;
};

}  // namespace cloudsvc
