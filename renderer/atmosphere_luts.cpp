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

bool AtmosphereLuts::froxels_serve(const ViewKey& a, const FrameUniforms& u) {
  const glm::vec3 sa(a.sun_dir), sb(u.sun_dir);
  if (!(std::abs(a.planet.y - u.planet.y) < 1.0f && glm::length(sa - sb) < 1e-4f &&
        std::abs(a.ap_params.x - u.ap_params.x) < 1.0f))
    return false;
  const float tx = u.view.x, ty = u.view.y;  // the camera's tan(half fov) per axis
  // not much coarser than a volume built for this camera would be
  if (a.ap_right.w > (1.0f + 2.0f * kApMargin) * tx || a.ap_up.w > (1.0f + 2.0f * kApMargin) * ty) return false;
  // the camera's frustum (a convex cone spanned by its four corner rays) inside the volume's
  const glm::vec3 f(u.camera_forward), r(u.camera_right), up(u.camera_up);
  const glm::vec3 af(a.ap_forward), ar(a.ap_right), au(a.ap_up);
  for (const float sx : {-1.0f, 1.0f})
    for (const float sy : {-1.0f, 1.0f}) {
      const glm::vec3 d = f + sx * tx * r + sy * ty * up;
      const float z = glm::dot(d, af);
      if (!(z > 0.0f) || std::abs(glm::dot(d, ar)) > a.ap_right.w * z || std::abs(glm::dot(d, au)) > a.ap_up.w * z)
        return false;
    }
  return true;
}

AtmosphereLuts::ViewLutUpdate AtmosphereLuts::plan_view_dependent(FrameUniforms& u) {
  ViewLutUpdate plan;
  const ViewKey camera{u.camera_forward,
                       glm::vec4(glm::vec3(u.camera_right), u.view.x * (1.0f + kApMargin)),
                       glm::vec4(glm::vec3(u.camera_up), u.view.y * (1.0f + kApMargin)),
                       u.planet, u.sun_dir, u.ap_params};
  plan.sky_view = !(last_sky_ && same_sky(*last_sky_, camera));
  if (plan.sky_view) last_sky_ = camera;
  plan.aerial_perspective = !(last_froxels_ && froxels_serve(*last_froxels_, u));
  if (plan.aerial_perspective) last_froxels_ = camera;
  u.ap_forward = last_froxels_->ap_forward;
  u.ap_right = last_froxels_->ap_right;
  u.ap_up = last_froxels_->ap_up;
  return plan;
}

void AtmosphereLuts::recompute(const ViewLutUpdate& plan) {
  if (!plan.sky_view && !plan.aerial_perspective) return;
  glBindTextureUnit(0, transmittance_.id());
  glBindTextureUnit(1, multiscatter_.id());
  glBindTextureUnit(2, irradiance_.id());
  if (plan.sky_view) {
    sky_view_prog_.use();
    glBindImageTexture(0, sky_view_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kSkyViewW, kSkyViewH);
  }
  if (plan.aerial_perspective) {
    ap_prog_.use();
    glBindImageTexture(0, ap_inscatter_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, ap_transmittance_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_2d(kApSize, kApSize);
  }
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
