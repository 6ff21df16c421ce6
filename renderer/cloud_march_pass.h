// The cloud march pass (shaders/cloud_march.comp): marches this frame's fresh cloud pixels
// (one in stride x stride, TemporalPlan) through the layer intervals and writes their
// radiance, transmittance and depth into the cloud buffer's fresh textures. Binds
// everything it reads: the frame buffers, the cloud field, the atmosphere lookups, the
// ground shadow map and light volume, the temporal uniforms. Needs a current GL context.
#pragma once

#include "renderer/cloud_buffer.h"
#include "renderer/cloud_pass_inputs.h"
#include "renderer/density_programs.h"
#include "renderer/ground_shadow_map.h"

namespace cloudsvc {

class CloudMarchPass {
 public:
  void run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer, const TemporalPlan& plan) const;

 private:
  DensityPrograms programs_{"cloud_march.comp"};
};

}  // namespace cloudsvc
