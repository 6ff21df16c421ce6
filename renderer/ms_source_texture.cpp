#include "renderer/ms_source_texture.h"

#include <vector>

#include "renderer/gpu_interface.h"
#include "renderer/model/ms_source_table.h"

namespace cloudsvc {

namespace {
const model::MsSourceTableShape& shape() { return model::ms_source_table().shape(); }
int depth_texels() { return shape().depth_bins * shape().n_sun * shape().n_tau; }
}  // namespace

MsSourceTexture::MsSourceTexture()
    : texture_(gl::make_texture_3d(GL_R32F, shape().directions.n_phi, shape().directions.n_mu, depth_texels(),
                                   GL_CLAMP_TO_EDGE)) {
  // The table's storage order [tau][sun][depth bin][mu][phi] is the texture's (x fastest).
  const std::vector<float>& v = model::ms_source_table().values();
  glTextureSubImage3D(texture_.id(), 0, 0, 0, 0, shape().directions.n_phi, shape().directions.n_mu, depth_texels(),
                      GL_RED, GL_FLOAT, v.data());
}

void MsSourceTexture::bind() const { glBindTextureUnit(gpu::tex::MS_SOURCE, texture_.id()); }

std::size_t MsSourceTexture::gpu_bytes() { return 4u * model::ms_source_table().shape().size(); }

}  // namespace cloudsvc
