// The per-frame uniform block (binding gpu::ubo::FRAME), the C++ side of
// shaders/frame_uniforms.glsl: every member has the same name, type and std140 offset on
// both sides (tests/gpu_interface_test.cpp compares each offset GL reports with offsetof).
// std140 rules kept by hand: a vec3 starts a 16-byte slot and the float after it fills the
// slot (hence alignas(16) on every vec3 here); scalars pack 4 bytes apart; arrays of
// structs and mat4 start on 16 bytes.
// Frame: "local" = East-North-Up axes at the camera, origin at the camera, metres.
// Written by pack_frame_uniforms (renderer/frame_uniforms_packing.h) only; no CPU code reads
// it back.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gpu_interface.h"

namespace cloudsvc {

struct CloudLayerGpu {
  float base_m, top_m;         // layer base and top altitude (m)
  float coverage;              // [0, 1]; 0 = not marched (clear, or culled for this frame)
  float density_scale;         // multiplies the extinction
  float extinction_max;        // sigma_t of the densest cloud (1/m)
  float g_hg, g_d, draine_alpha, w_d;  // Jendersie & d'Eon 2023 phase fit (droplet size)
  float base_noise_frequency;    // 1 / base-noise period (1/m)
  float detail_noise_frequency;  // 1 / detail-noise period (1/m)
  float detail_erosion;          // how deep the detail noise erodes the base shape
  float bottom_ramp, top_ramp, top_weight;  // vertical profile (weather::CloudTypeTraits)
  float noise_vertical_scale;    // k: altitude scaled by k in noise space
  alignas(16) glm::vec3 base_noise_offset;  // camera's field position, base-noise periods, wrapped
  int stratiform;                            // 1: sheet not driven by the map's type channel
  alignas(16) glm::vec3 detail_noise_offset;  // ... in detail-noise periods, wrapped
  int dome;                                    // 1: individual cumulus domes (cumulus_domes.glsl, slot = layer)
  alignas(16) glm::vec4 anvil;  // weather::Anvil: spread (0: none), base, top, density_ratio
  glm::mat4 noise_rotation;  // upper 3x3: local ENU -> noise space (weather/noise_shaping.h S times the wind-rotated ECEF axes)
  // optical depths scale by this onto the diffuse source table's droplets
  // (model::ms_similarity_scale of the layer's phase function)
  float ms_similarity;
  int coverage_channel = -1;  // weather::CloudLayer::coverage_channel: -1 R-modulated, 0-3 a layer-coverage channel
  float base_relief = 0.0f;  // weather::CloudTypeTraits::base_relief (fraction of the layer's depth)
  float pad2 = 0.0f;         // std140 aligns the next member to a vec4
  // the noises' stochastic tiling (weather/noise_tiling.h, noise_tiling.glsl): floor(camera's
  // field position / period) per axis, and the four lattices' hash seeds
  alignas(16) glm::ivec3 base_noise_cell;
  alignas(16) glm::ivec3 detail_noise_cell;
  alignas(16) glm::uvec4 base_tiling_seeds;
  glm::uvec4 detail_tiling_seeds;
  // transmittance of the layer's full nominal optical depth extinction_max * density_scale
  // * thickness (model::slab_flux_table): element j < 11 for the sun's beam at the table's
  // zenith cosine mu_j (kSlabFluxMuMin + j kSlabFluxMuStep), element 11 for diffuse light
  glm::vec4 ground_transmittance[3];
};

struct FrameUniforms {
  glm::mat4 enu_to_ecef;  // rotation (upper 3x3): local ENU axes -> ECEF axes
  alignas(16) glm::vec3 camera_forward;  // unit, local ENU
  float tan_half_fov_x;  // half extents of the image window (ImageWindow::half_x, half_y)
  alignas(16) glm::vec3 camera_right;
  float tan_half_fov_y;
  alignas(16) glm::vec3 camera_up;
  float pixel_angle_rad;  // angle one cloud pixel subtends at the image centre
  alignas(16) glm::vec3 sun_direction;  // unit vector to the sun, local ENU
  float weather_blend;                  // weight of the next weather keyframe [0, 1]
  // frustum of the aerial-perspective volume (AtmosphereLuts::plan_view_dependent): its
  // forward, right and up axes and the tangents of its half width and height
  alignas(16) glm::vec3 ap_forward;
  float ap_max_distance_m;  // depth of the aerial-perspective volume
  alignas(16) glm::vec3 ap_right;
  float ap_tan_half_width;
  alignas(16) glm::vec3 ap_up;
  float ap_tan_half_height;
  glm::vec2 image_size_px;  // frame width, height
  float shell_radius_m;     // R of the cloud shell and ground sphere (osculating at the camera)
  float camera_altitude_m;  // h; the sphere centre is at (0, 0, -(R + h))
  float ground_altitude_m;
  float march_reach_m;        // farthest cloud a ray can see over the horizon
  float weather_map_height;   // texels
  float step_growth_ref_m;    // t_ref of the primary-step distribution (0 = uniform steps)
  int primary_steps, light_steps, ground_shadow_steps;
  float light_march_cutoff_tau;  // light marches stop past this optical depth (1e30 = never)
  float long_step_factor;        // probe steps in empty air are this many times longer (1 = off)
  float detail_noise_mean;       // mean value of the detail noise (level of detail)
  float base_noise_mean;         // mean value of the base noise (the tiling's blend)
  int level_of_detail;           // 1: detail noise and light steps follow the pixel footprint
  int coverage_pyramid;          // 1: the coverage max-pyramid is bound and queried
  int layer_count;
  int frame_index;                // mod 65536: jitter sequences
  int count_density_evaluations;  // 1: add them to the frame counters
  int footprint_jitter;           // 1: rays through a per-frame point of the pixel
  float view_center_tan_x;        // the image window's centre (ImageWindow::center_x, center_y):
  float view_center_tan_y;        // 0 for a symmetric view
  float view_near_m;              // ViewRequest::near_m, far_m: clouds drawn between these planes
  float view_far_m;               // along camera_forward (cloud_clip); far 1e30 = no plane
  float aerosol_scale;             // factor on the aerosol's scattering and extinction (FrameContext)
  int column_steps;                // RenderQuality::column_steps
  int sun_slab_tilt;               // RenderQuality::sun_slab_tilt, with column_steps > 0
  glm::vec4 noise_quantiles[4];   // base-noise value below which a fraction i/15 lies, i = 0..15
  glm::vec4 weather_pole_south;   // weather map value at the south pole (row mean)
  glm::vec4 weather_pole_north;   // ... at the north pole
  glm::vec4 layer_coverage_pole_south;  // the map's layer-coverage channels at the south pole (row mean)
  glm::vec4 layer_coverage_pole_north;  // ... at the north pole
  glm::vec4 ground_albedo;        // rgb: the ground's Lambertian albedo (FrameContext::ground_albedo);
                                  // w: 1 where tiles have set some of it (ground_albedo_at)
  glm::vec4 ground_albedo_poles;  // the albedo map's (R, G) at the south pole, then the north's
  CloudLayerGpu layers[gpu::kMaxLayers];
};

static_assert(sizeof(CloudLayerGpu) == 19 * 16, "std140 layout");
static_assert(sizeof(FrameUniforms) == 64 + 24 * 16 + gpu::kMaxLayers * 19 * 16, "std140 layout");

}  // namespace cloudsvc
