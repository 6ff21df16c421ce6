// The composite pass (shaders/composite.comp): the full-resolution frame from this frame's
// resolved cloud buffer over the sky (sky-view LUT, sun disk) or the ground (lit through
// the clouds' shadows, seen through the aerial perspective), into the frame target, which
// read_back copies to the CPU. Binds what it reads: the frame buffers, the temporal
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
#include "renderer/gl/shader_program.h"
#include "renderer/ground_shadow_map.h"

namespace cloudsvc {

class CompositePass {
 public:
  CompositePass();
  // Sizes the frame target (w x h pixels).
  void ensure_size(int w, int h);
  // shadows_per_pixel: the ground's cloud shadows marched at every pixel (qualities without
  // the ground shadow map) instead of read from the map.
  void run(const CloudPassInputs& inputs, const GroundShadowMap& shadows, const CloudBuffer& buffer,
           bool shadows_per_pixel);
  // The frame target into img (rgba float, rows from the top; sets width and height).
  void read_back(FrameImage& img) const;
  std::size_t gpu_bytes() const { return static_cast<std::size_t>(w_) * h_ * 16; }

 private:
  gl::ShaderProgram program_;                           // shadows from the map: no density code
  DensityPrograms per_pixel_programs_{"composite.comp", {"CLOUDSVC_GROUND_SHADOWS_PER_PIXEL"}};
  gl::Texture target_;
  int w_ = 0, h_ = 0;
};

}  // namespace cloudsvc
