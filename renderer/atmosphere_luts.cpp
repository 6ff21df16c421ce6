#include "renderer/atmosphere_luts.h"

#include <algorithm>
#include <cmath>

#include <cmath>

namespace cloudsvc {

void dispatch_2d(int w, int h, int d) {
  glDispatchCompute(static_cast<GLuint>((w + 7) / 8), static_cast<GLuint>((h + 7) / 8), static_cast<GLuint>(d));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

AtmosphereLuts::AtmosphereLuts()
    : sky_view_prog_(gl::ShaderProgram::compute("sky_view_lut.comp")),
      ap_prog_(gl::ShaderProgram::compute("aerial_perspective.comp")),
      transmittance_(gl::make_texture_2d(GL_RGBA32F, kTransmittanceW, kTransmittanceH, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      multiscatter_(gl::make_texture_2d(GL_RGBA32F, kMultiscatterSize, kMultiscatterSize, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      irradiance_(gl::make_texture_2d(GL_RGBA32F, kIrradianceSize, kIrradianceSize, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      sky_view_(gl::make_texture_2d(GL_RGBA32F, kSkyViewW, kSkyViewH, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      ap_inscatter_(gl::make_texture_3d(GL_RGBA32F, kApSize, kApSize, kApSize, GL_CLAMP_TO_EDGE)),
      ap_transmittance_(gl::make_texture_3d(GL_RGBA32F, kApSize, kApSize, kApSize, GL_CLAMP_TO_EDGE)) {
  // Static LUTs, in dependency order: transmittance -> multiple scattering -> irradiance.
  {
    auto prog = gl::ShaderProgram::compute("transmittance_lut.comp");
    prog.use();
    glBindImageTexture(0, transmittance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kTransmittanceW, kTransmittanceH);
  }
  {
    auto prog = gl::ShaderProgram::compute("multiscatter_lut.comp");
    prog.use();
    glBindTextureUnit(0, transmittance_.id());
    glBindImageTexture(0, multiscatter_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kMultiscatterSize, kMultiscatterSize);
  }
  {
    auto prog = gl::ShaderProgram::compute("sky_irradiance_lut.comp");
    prog.use();
    glBindTextureUnit(0, transmittance_.id());
    glBindTextureUnit(1, multiscatter_.id());
    glBindImageTexture(0, irradiance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kIrradianceSize, kIrradianceSize);
  }
}

bool AtmosphereLuts::same_sky(const ViewKey& a, const ViewKey& b) {
  const float zenith_a = std::acos(std::clamp(a.sun_dir.z, -1.0f, 1.0f));
  const float zenith_b = std::acos(std::clamp(b.sun_dir.z, -1.0f, 1.0f));
  return std::abs(a.planet.y - b.planet.y) < 1.0f && std::abs(zenith_a - zenith_b) < 1e-4f;
}

bool AtmosphereLuts::same_froxels(const ViewKey& a, const ViewKey& b) {
  const glm::vec3 sa(a.sun_dir), sb(b.sun_dir);
  return a.camera_forward == b.camera_forward && a.camera_right == b.camera_right && a.camera_up == b.camera_up &&
         a.view == b.view && std::abs(a.planet.y - b.planet.y) < 1.0f && glm::length(sa - sb) < 1e-4f &&
         std::abs(a.ap_params.x - b.ap_params.x) < 1.0f;
}

AtmosphereLuts::ViewLutUpdate AtmosphereLuts::update_view_dependent(const FrameUniforms& u) {
  const ViewKey key{u.camera_forward, u.camera_right, u.camera_up, u.view, u.planet, u.sun_dir, u.ap_params};
  ViewLutUpdate done;
  done.sky_view = !(last_sky_ && same_sky(*last_sky_, key));
  done.aerial_perspective = !(last_froxels_ && same_froxels(*last_froxels_, key));
  if (!done.sky_view && !done.aerial_perspective) return done;
  glBindTextureUnit(0, transmittance_.id());
  glBindTextureUnit(1, multiscatter_.id());
  glBindTextureUnit(2, irradiance_.id());
  if (done.sky_view) {
    last_sky_ = key;
    sky_view_prog_.use();
    glBindImageTexture(0, sky_view_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kSkyViewW, kSkyViewH);
  }
  if (done.aerial_perspective) {
    last_froxels_ = key;
    ap_prog_.use();
    glBindImageTexture(0, ap_inscatter_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, ap_transmittance_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kApSize, kApSize);
  }
  return done;
}

void AtmosphereLuts::bind_for_scene() const {
  glBindTextureUnit(0, transmittance_.id());
  glBindTextureUnit(1, multiscatter_.id());
  glBindTextureUnit(2, irradiance_.id());
  glBindTextureUnit(6, sky_view_.id());
  glBindTextureUnit(7, ap_inscatter_.id());
  glBindTextureUnit(8, ap_transmittance_.id());
}

}  // namespace cloudsvc
