#include "renderer/ground_shadow_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/gl/compute_dispatch.h"
#include "renderer/temporal_reprojection.h"

namespace cloudsvc {

namespace {

double horizontal_distance(const FrameContext& a, const FrameContext& b) {
  const glm::dvec3 d = b.camera_ecef - a.camera_ecef;
  const glm::dvec3 up = a.enu_to_ecef[2];
  return glm::length(d - glm::dot(d, up) * up);
}

}  // namespace

double shadow_map_warp(double alt_m) { return std::max(kMinWarpM, 2.0 * alt_m); }

std::string shadow_map_stale_reason(const ShadowMapKey& key, const FrameContext& frame,
                                    std::uint64_t weather_generation) {
  if (weather_generation != key.weather_generation) return "weather changed";
  const double sun_deg = std::acos(std::clamp(glm::dot(frame.sun_ecef, key.anchor.sun_ecef), -1.0, 1.0)) * 180.0 / M_PI;
  if (sun_deg > kSunTolDeg) return "sun moved";
  if (horizontal_distance(key.anchor, frame) > kReachFraction * key.warp_m) return "camera left the core";
  const double k = shadow_map_warp(frame.camera_altitude_m);
  if (k > 1.5 * key.warp_m || k < key.warp_m / 1.5) return "altitude changed";
  // drift of each layer's field under the camera since the build
  const Reprojection r = make_reprojection(key.anchor, frame);
  const glm::dvec3 under_camera(0.0, 0.0, -frame.camera_altitude_m);
  for (int i = 0; i < frame.layer_count; ++i) {
    const glm::dvec3 with_wind = glm::dvec3(r.transform[i] * glm::dvec4(under_camera, 1.0));
    const glm::dvec3 without = glm::dvec3(r.transform[kGroundTransform] * glm::dvec4(under_camera, 1.0));
    if (glm::length(with_wind - without) > kReachFraction * key.warp_m) return "wind drift";
  }
  return "";
}

GroundShadowMap::GroundShadowMap()
    : map_(gl::make_texture_2d_array(GL_R32F, kSize, kSize, gpu::kMaxLayers)),
      volume_(gl::make_texture_3d(GL_R32F, kVolumeSize, kVolumeSize, kVolumeLevels * gpu::kMaxLayers, GL_CLAMP_TO_EDGE)),
      uniforms_(gl::make_buffer(sizeof(ShadowMapUniforms), nullptr, GL_DYNAMIC_DRAW)) {}

void GroundShadowMap::build(const FrameContext& frame, const CloudPassInputs& inputs, const ShadowMapUniforms& su,
                            bool light_volume, bool column_volume) {
  glNamedBufferSubData(uniforms_.id(), 0, sizeof(ShadowMapUniforms), &su);
  inputs.bind();
  glBindBufferBase(GL_UNIFORM_BUFFER, gpu::ubo::SHADOW_MAP, uniforms_.id());
  inputs.use(build_prog_);
  glBindImageTexture(gpu::img::SHADOW_MAP_OUT, map_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  gl::dispatch_2d(kSize, kSize, frame.layer_count);
  if (light_volume) {
    inputs.use(volume_prog_);
    glBindImageTexture(gpu::img::LIGHT_VOLUME_OUT, volume_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    gl::dispatch_2d(kVolumeSize, kVolumeSize, frame.layer_count * kVolumeLevels);
  }
  if (column_volume) {
    if (!columns_)  // allocated when first asked for: kColumnVolumeBytes a renderer without columns never holds
      columns_ = gl::make_texture_3d(GL_RG16F, gpu::kColumnVolumeTexels, gpu::kColumnVolumeTexels,
                                     (gpu::kColumnVolumeLevels + 1) * gpu::kMaxLayers, GL_CLAMP_TO_EDGE);
    inputs.use(column_prog_);
    glBindImageTexture(gpu::img::COLUMN_VOLUME_OUT, columns_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG16F);
    gl::dispatch_2d(gpu::kColumnVolumeTexels, gpu::kColumnVolumeTexels, frame.layer_count);
  }
}

bool GroundShadowMap::update(const FrameContext& frame, const CloudPassInputs& inputs,
                             std::uint64_t weather_generation, int light_steps, bool per_pixel, bool light_volume,
                             int column_steps, int column_march_steps, bool needed) {
  ShadowMapUniforms su{};
  for (auto& m : su.to_anchor) m = glm::mat4(1.0f);
  su.column_march_steps = std::max(column_march_steps, 0);
  const auto upload = [&] { glNamedBufferSubData(uniforms_.id(), 0, sizeof(ShadowMapUniforms), &su); };
  if (!needed) {  // everything off: no map, no per-pixel shadows, no volume this frame
    upload();
    return false;
  }
  const bool night = frame.sun_enu.z < std::sin(kNightDeg * M_PI / 180.0);
  bool rebuilt = false;
  if (night || frame.layer_count == 0) {
    key_.reset();
  } else if (per_pixel) {
    su.march_per_pixel = 1;
  } else {
    const bool volume_missing = light_volume && key_ && (!key_->light_volume || key_->light_steps != light_steps);
    const bool columns_missing = column_steps > 0 && key_ && key_->column_steps != column_steps;
    const bool stale = !key_ || volume_missing || columns_missing ||
                       !shadow_map_stale_reason(*key_, frame, weather_generation).empty();
    if (stale)
      key_ = ShadowMapKey{frame, weather_generation, shadow_map_warp(frame.camera_altitude_m), light_volume, light_steps,
                          column_steps};
    su.warp_m = static_cast<float>(key_->warp_m);
    su.map_texels = kSize;
    su.map_valid = 1;
    su.volume_levels = kVolumeLevels;
    su.volume_texels = kVolumeSize;
    if (stale) {
      build(frame, inputs, su, light_volume, column_steps > 0);  // this frame is the anchor: identity transforms, no volume read
      rebuilt = true;
    }
    const Reprojection r = make_reprojection(key_->anchor, frame);
    for (int i = 0; i < gpu::kMaxLayers; ++i) su.to_anchor[i] = glm::mat4(r.transform[i]);
    su.volume_valid = light_volume ? 1 : 0;
    su.column_valid = column_steps > 0 ? 1 : 0;
  }
  upload();
  return rebuilt;
}

void GroundShadowMap::bind_lookups() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, gpu::ubo::SHADOW_MAP, uniforms_.id());
  glBindTextureUnit(gpu::tex::GROUND_SHADOW_MAP, map_.id());
  glBindTextureUnit(gpu::tex::LIGHT_VOLUME, volume_.id());
  glBindTextureUnit(gpu::tex::COLUMN_VOLUME, columns_.id());  // 0 until first built: read only when column_valid
}

}  // namespace cloudsvc
