#include "renderer/ms_source_textures.h"

#include <stdexcept>
#include <vector>

#include "renderer/gpu_interface.h"
#include "renderer/model/ms_source_table.h"

namespace cloudsvc {

namespace {
const model::MsSourceTableShape& sun_shape() { return model::ms_source_table().shape(); }
const model::MsSourceTableShape& diffuse_shape() { return model::ms_diffuse_incidence_table().shape(); }

gl::Texture make_sun_texture() {
  const model::MsSourceTableShape& s = sun_shape();
  const int depth = s.depth_bins * s.n_sun * s.n_tau;
  gl::Texture t = gl::make_texture_3d(GL_R32F, s.directions.n_phi, s.directions.n_mu, depth, GL_CLAMP_TO_EDGE);
  // The table's storage order [tau][sun][depth bin][mu][phi] is the texture's (x fastest).
  const std::vector<float>& v = model::ms_source_table().values();
  glTextureSubImage3D(t.id(), 0, 0, 0, 0, s.directions.n_phi, s.directions.n_mu, depth, GL_RED, GL_FLOAT, v.data());
  return t;
}

gl::Texture make_diffuse_texture() {
  const model::MsSourceTableShape& s = diffuse_shape();
  const model::MsSourceTableShape& sun = sun_shape();
  if (s.n_sun != 1 || s.n_tau != sun.n_tau || s.depth_bins != sun.depth_bins ||
      s.directions.n_mu != sun.directions.n_mu)
    throw std::runtime_error("ms source textures: the diffuse table's grid is not the sun table's");
  const int depth = s.depth_bins * s.n_tau;
  // [tau][depth bin][mu][phi] -> [tau][depth bin][mu]: the azimuth node 0 (all are equal)
  const std::vector<float>& v = model::ms_diffuse_incidence_table().values();
  std::vector<float> column;
  column.reserve(v.size() / s.directions.n_phi);
  for (std::size_t i = 0; i < v.size(); i += s.directions.n_phi) column.push_back(v[i]);
  gl::Texture t = gl::make_texture_3d(GL_R32F, 1, s.directions.n_mu, depth, GL_CLAMP_TO_EDGE);
  glTextureSubImage3D(t.id(), 0, 0, 0, 0, 1, s.directions.n_mu, depth, GL_RED, GL_FLOAT, column.data());
  return t;
}
}  // namespace

MsSourceTextures::MsSourceTextures() : sun_(make_sun_texture()), diffuse_(make_diffuse_texture()) {}

void MsSourceTextures::bind() const {
  glBindTextureUnit(gpu::tex::MS_SOURCE, sun_.id());
  glBindTextureUnit(gpu::tex::MS_DIFFUSE_INCIDENCE, diffuse_.id());
}

std::size_t MsSourceTextures::gpu_bytes() {
  return 4u * (sun_shape().size() + diffuse_shape().size() / diffuse_shape().directions.n_phi);
}

}  // namespace cloudsvc
