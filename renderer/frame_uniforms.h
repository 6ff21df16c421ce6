// CPU mirror of shaders/frame_uniforms.glsl (std140: only vec4/mat4 members, so the C++
// layout matches without padding rules). Keep the two in sync.
#pragma once

#include <glm/glm.hpp>

namespace cloudsvc {

struct CloudLayerGpu {
  glm::vec4 altitude;       // base m, top m, coverage, density scale
  glm::vec4 optics;         // sigma_t max 1/m, g_HG, g_D, alpha
  glm::vec4 optics2;        // w_D, 1/base period, 1/detail period, detail erosion
  glm::vec4 profile;        // bottom ramp, top ramp, top weight, noise vertical scale
  glm::vec4 base_offset;    // base noise offset (tile units), w = stratiform flag
  glm::vec4 detail_offset;  // detail noise offset (tile units)
  glm::mat4 noise_rotation;  // local ENU -> ECEF axes of the wind-rotated cloud field
};

constexpr int kGpuMaxLayers = 4;

struct FrameUniforms {
  glm::mat4 enu_to_ecef;
  glm::vec4 camera_forward;
  glm::vec4 camera_right;
  glm::vec4 camera_up;
  glm::vec4 view;
  glm::vec4 planet;
  glm::vec4 sun_dir;
  glm::vec4 sun_irradiance;
  glm::vec4 ground_albedo;
  glm::vec4 quality;
  glm::vec4 ms_params;
  glm::vec4 ap_params;
  glm::vec4 march;   // long-step factor, LOD on, pixel angle (rad), mean detail-noise value
  glm::vec4 skips;   // coverage pyramid on (1/0), light-march optical-depth cut-off (1e30 = none), unused x2
  // frustum of the aerial-perspective volume (AtmosphereLuts::plan_view_dependent): its
  // forward, right (w: tan of half its width) and up (w: tan of half its height) axes
  glm::vec4 ap_forward, ap_right, ap_up;
  glm::ivec4 counts;
  glm::vec4 noise_quantiles[4];  // base-noise quantiles at p = i / 15, i = 0..15
  glm::vec4 weather_pole_south;  // weather map value at the south pole (row mean)
  glm::vec4 weather_pole_north;  // ... and at the north pole
  CloudLayerGpu layers[kGpuMaxLayers];
};

static_assert(sizeof(CloudLayerGpu) == 10 * 16, "std140 layout");
static_assert(sizeof(FrameUniforms) == 64 + 23 * 16 + kGpuMaxLayers * 10 * 16, "std140 layout");

}  // namespace cloudsvc
