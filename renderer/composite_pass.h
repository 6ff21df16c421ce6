// The composite pass (shaders/composite.comp): the full-resolution frame from this frame's
// resolved cloud buffer over the sky (sky-view LUT, sun disk) or the ground (lit through
// the clouds' shadows, seen through the aerial perspective), into a view's frame target
// (frame_target.h). Binds what it reads: the frame buffers, the temporal
// uniforms, the cloud field (for per-pixel ground shadows), the atmosphere lookups, the
// ground shadow map and the resolved cloud radiance. Needs a current GL 4.5 context.
#pragma once

#include <string>
#include <vector>

#include "renderer/api/frame_image.h"
#include "renderer/cloud_buffer.h"
#include "renderer/cloud_pass_inputs.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/density_programs.h"
#include "renderer/frame_target.h"
#include "renderer/gl/shader_program.h"
#include "renderer/ground_shadow_map.h"

namespace cloudsvc {

class CompositePass {
 public:
  CompositePass();
  // Composites into the target, whose size is the frame's. shadows_per_pixel: the ground's
  // cloud shadows marched at every pixel (qualities without the ground shadow map) instead
  // of read from the map.
  void run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer,
           const FrameTarget& target, bool shadows_per_pixel);

 private:
  gl::ShaderProgram program_;                           // shadows from the map: no density code
  DensityPrograms per_pixel_programs_{"composite.comp", {"CLOUDSVC_GROUND_SHADOWS_PER_PIXEL"}};
};

}  // namespace cloudsvc
