#include "renderer/ground_albedo_texture.h"

#include "renderer/gpu_interface.h"

namespace cloudsvc {

GroundAlbedoTexture::GroundAlbedoTexture()
    : texture_(gl::make_texture_2d(GL_RG32F, 1, 1, GL_REPEAT, GL_CLAMP_TO_EDGE)), bytes_(8) {
  const float zero[2] = {0.0f, 0.0f};
  glTextureSubImage2D(texture_.id(), 0, 0, 0, 1, 1, GL_RG, GL_FLOAT, zero);
}

void GroundAlbedoTexture::update(const weather::GroundAlbedoMap& map) {
  if (uploaded_ && map.version() == version_) return;
  version_ = map.version();
  uploaded_ = true;
  any_ = map.any();
  if (!any_) return;  // the shaders read the global albedo only
  const weather::WeatherMap& m = map.texels();
  if (m.width != width_ || m.height != height_) {
    texture_ = gl::make_texture_2d(GL_RG32F, m.width, m.height, GL_REPEAT, GL_CLAMP_TO_EDGE);
    width_ = m.width;
    height_ = m.height;
    bytes_ = static_cast<std::size_t>(width_) * height_ * 8;
  }
  // RGBA texels into the RG texture: GL keeps R and G and drops B and A (both 0)
  glTextureSubImage2D(texture_.id(), 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, m.rgba.data());
  float south[4], north[4];
  m.pole_value(false, south);
  m.pole_value(true, north);
  poles_ = {south[0], south[1], north[0], north[1]};
}

void GroundAlbedoTexture::bind() const { glBindTextureUnit(gpu::tex::GROUND_ALBEDO, texture_.id()); }

void GroundAlbedoTexture::describe(GpuResourceSummary& resources) const {
  resources.ground_albedo_map = any_;
  resources.ground_albedo_poles = poles_;
}

}  // namespace cloudsvc
