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
#include "renderer/model/mie_phase_table.h"

namespace cloudsvc {

class CloudMarchPass {
 public:
  // phase: kMie compiles the march with the layers' tabulated Mie phase functions
  // (CLOUDSVC_MIE_PHASE; the pass then needs CloudPassInputs::phase).
  explicit CloudMarchPass(model::CloudPhaseModel phase = model::CloudPhaseModel::kFit)
      : programs_("cloud_march.comp", phase == model::CloudPhaseModel::kMie
                                          ? std::vector<std::string>{"CLOUDSVC_MIE_PHASE"}
                                          : std::vector<std::string>{}) {}

  void run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer, const TemporalPlan& plan) const;

 private:
  DensityPrograms programs_;
};

}  // namespace cloudsvc
