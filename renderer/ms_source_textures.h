// The multiple-scattering source tables (renderer/model/ms_source_table.h) on the GPU, each
// an R32F 3-D texture:
// * the sun's (gpu::tex::MS_SOURCE): x = relative azimuth of the scattered light (n_phi
//   nodes), y = its zenith cosine (n_mu), z = depth bin + depth_bins * (sun node + n_sun *
//   tau node);
// * the diffuse light's (gpu::tex::MS_DIFFUSE_INCIDENCE; model::ms_diffuse_incidence_table): no
//   azimuth (the table holds the same value at every azimuth node; x = 1 texel),
//   y = zenith cosine, z = depth bin + depth_bins * tau node.
// Linear filtering interpolates within one block; the lookups in
// shaders/ms_source_lookup.glsl blend the blocks around their (tau, sun) and keep their
// depth coordinate between a block's first and last bin centres, so no block bleeds into
// the next. Uploaded once; needs a current GL 4.5 context.
#pragma once

#include <cstddef>

#include "renderer/gl/gl_objects.h"

namespace cloudsvc {

class MsSourceTextures {
 public:
  // Throws std::runtime_error if the two tables' optical-depth, depth or zenith grids differ
  // (the shaders index both with the same constants).
  MsSourceTextures();
  void bind() const;
  static std::size_t gpu_bytes();

 private:
  gl::Texture sun_;
  gl::Texture diffuse_;
};

}  // namespace cloudsvc
