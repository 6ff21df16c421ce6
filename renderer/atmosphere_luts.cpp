#include "renderer/atmosphere_luts.h"

#include <algorithm>
#include <cmath>

#include "renderer/gl/compute_dispatch.h"

namespace cloudsvc {

AtmosphereLuts::AtmosphereLuts()
    : transmittance_prog_(gl::ShaderProgram::compute("transmittance_lut.comp")),
      multiscatter_prog_(gl::ShaderProgram::compute("multiscatter_lut.comp")),
      irradiance_prog_(gl::ShaderProgram::compute("sky_irradiance_lut.comp")),
      sky_view_prog_(gl::ShaderProgram::compute("sky_view_lut.comp")),
      ap_prog_(gl::ShaderProgram::compute("aerial_perspective.comp")),
      transmittance_(gl::make_texture_2d(GL_RGBA32F, kTransmittanceW, kTransmittanceH, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      multiscatter_(gl::make_texture_2d(GL_RGBA32F, kSunLutMuNodes, kSunLutAltNodes, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      irradiance_(gl::make_texture_2d(GL_RGBA32F, kSunLutMuNodes, kSunLutAltNodes, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      sky_view_(gl::make_texture_2d(GL_RGBA32F, kSkyViewW, kSkyViewH, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE)),
      ap_inscatter_(gl::make_texture_3d(GL_RGBA32F, kApSize, kApSize, kApSize, GL_CLAMP_TO_EDGE)),
      ap_transmittance_(gl::make_texture_3d(GL_RGBA32F, kApSize, kApSize, kApSize, GL_CLAMP_TO_EDGE)) {}

bool AtmosphereLuts::same_sky(const ViewKey& a, const ViewKey& b) {
  const double zenith_a = std::acos(std::clamp(a.sun_enu.z, -1.0, 1.0));
  const double zenith_b = std::acos(std::clamp(b.sun_enu.z, -1.0, 1.0));
  return std::abs(a.camera_altitude_m - b.camera_altitude_m) < 1.0 && std::abs(zenith_a - zenith_b) < 1e-4;
}

bool AtmosphereLuts::froxels_serve(const ViewKey& a, const FrameContext& c) {
  if (!(std::abs(a.camera_altitude_m - c.camera_altitude_m) < 1.0 && glm::length(a.sun_enu - c.sun_enu) < 1e-4 &&
        std::abs(a.ap_max_distance_m - c.ap_max_distance_m()) < 1.0))
    return false;
  const ImageWindow& w = c.window;
  const ApFrustum& v = a.frustum;
  // not much coarser than a volume built for this camera would be
  if (v.tan_half_width > (1.0 + 2.0 * kApMargin) * w.bound_x() || v.tan_half_height > (1.0 + 2.0 * kApMargin) * w.bound_y())
    return false;
  // the camera's frustum (a convex cone spanned by its four corner rays) inside the volume's
  for (const double sx : {-1.0, 1.0})
    for (const double sy : {-1.0, 1.0}) {
      const glm::dvec3 d = c.axes.forward + (w.center_x + sx * w.half_x) * c.axes.right +
                           (w.center_y + sy * w.half_y) * c.axes.up;
      const double z = glm::dot(d, v.forward);
      if (!(z > 0.0) || std::abs(glm::dot(d, v.right)) > v.tan_half_width * z ||
          std::abs(glm::dot(d, v.up)) > v.tan_half_height * z)
        return false;
    }
  return true;
}

AtmosphereLuts::ViewLutUpdate AtmosphereLuts::plan_view_dependent(FrameContext& c) {
  ViewLutUpdate plan;
  plan.atmosphere = last_aerosol_scale_ != c.aerosol_scale;
  if (plan.atmosphere) {  // every LUT reads the air
    last_aerosol_scale_ = c.aerosol_scale;
    last_sky_.reset();
    last_froxels_.reset();
  }
  // a volume built now: the symmetric frustum around the camera's, kApMargin wider per axis
  const ViewKey camera{ApFrustum{c.axes.forward, c.axes.right, c.axes.up, c.window.bound_x() * (1.0 + kApMargin),
                                 c.window.bound_y() * (1.0 + kApMargin)},
                       c.camera_altitude_m, c.ap_max_distance_m(), c.sun_enu};
  plan.sky_view = !(last_sky_ && same_sky(*last_sky_, camera));
  if (plan.sky_view) last_sky_ = camera;
  plan.aerial_perspective = !(last_froxels_ && froxels_serve(*last_froxels_, c));
  if (plan.aerial_perspective) last_froxels_ = camera;
  c.ap = last_froxels_->frustum;
  return plan;
}

void AtmosphereLuts::recompute(const ViewLutUpdate& plan, const FrameBuffers& frame) {
  if (!plan.atmosphere && !plan.sky_view && !plan.aerial_perspective) return;
  frame.bind();
  if (plan.atmosphere) {  // in dependency order: transmittance -> multiple scattering -> irradiance
    transmittance_prog_.use();
    glBindImageTexture(gpu::img::LUT_OUT, transmittance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::dispatch_2d(kTransmittanceW, kTransmittanceH);
    multiscatter_prog_.use();
    glBindTextureUnit(gpu::tex::TRANSMITTANCE_LUT, transmittance_.id());
    glBindImageTexture(gpu::img::LUT_OUT, multiscatter_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::dispatch_2d(kSunLutMuNodes, kSunLutAltNodes);
    irradiance_prog_.use();
    glBindTextureUnit(gpu::tex::MULTISCATTER_LUT, multiscatter_.id());
    glBindImageTexture(gpu::img::LUT_OUT, irradiance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::dispatch_2d(kSunLutMuNodes, kSunLutAltNodes);
  }
  glBindTextureUnit(gpu::tex::TRANSMITTANCE_LUT, transmittance_.id());
  glBindTextureUnit(gpu::tex::MULTISCATTER_LUT, multiscatter_.id());
  glBindTextureUnit(gpu::tex::SKY_IRRADIANCE_LUT, irradiance_.id());
  if (plan.sky_view) {
    sky_view_prog_.use();
    glBindImageTexture(gpu::img::LUT_OUT, sky_view_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::dispatch_2d(kSkyViewW, kSkyViewH);
  }
  if (plan.aerial_perspective) {
    ap_prog_.use();
    glBindImageTexture(gpu::img::AP_INSCATTER_OUT, ap_inscatter_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(gpu::img::AP_TRANSMITTANCE_OUT, ap_transmittance_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::dispatch_2d(kApSize, kApSize);
  }
}

void AtmosphereLuts::bind_lookups() const {
  glBindTextureUnit(gpu::tex::TRANSMITTANCE_LUT, transmittance_.id());
  glBindTextureUnit(gpu::tex::MULTISCATTER_LUT, multiscatter_.id());
  glBindTextureUnit(gpu::tex::SKY_IRRADIANCE_LUT, irradiance_.id());
  glBindTextureUnit(gpu::tex::SKY_VIEW_LUT, sky_view_.id());
  glBindTextureUnit(gpu::tex::AP_INSCATTER, ap_inscatter_.id());
  glBindTextureUnit(gpu::tex::AP_TRANSMITTANCE, ap_transmittance_.id());
}

}  // namespace cloudsvc
