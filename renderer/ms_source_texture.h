// The multiple-scattering source table (renderer/model/ms_source_table.h) on the GPU: an
// R32F 3-D texture with x = relative azimuth of the scattered light (n_phi nodes), y = its
// zenith cosine (n_mu), z = depth bin + depth_bins * (sun node + n_sun * tau node). Linear
// filtering interpolates within one (tau, sun) block; ms_diffuse_source in
// shaders/cloud_lighting.glsl blends the four blocks around its (tau, sun) and keeps its
// depth coordinate between the block's first and last bin centres, so no block bleeds into
// the next. Uploaded once; needs a current GL 4.5 context.
#pragma once

#include <cstddef>

#include "renderer/gl/gl_objects.h"

namespace cloudsvc {

class MsSourceTexture {
 public:
  MsSourceTexture();
  // Binds the texture at gpu::tex::MS_SOURCE.
  void bind() const;
  static std::size_t gpu_bytes();

 private:
  gl::Texture texture_;
};

}  // namespace cloudsvc
