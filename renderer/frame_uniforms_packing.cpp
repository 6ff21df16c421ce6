#include "renderer/frame_uniforms_packing.h"

#include <algorithm>
#include <cmath>

#include "renderer/model/droplet_optics.h"
#include "renderer/model/ms_source_table.h"
#include "renderer/model/phase_function.h"
#include "renderer/model/slab_flux_table.h"
#include "weather/noise_tiling.h"

namespace cloudsvc {

namespace {

// Fractional part of x / period in [0, 1), computed in double so that offsets of
// thousands of km (or decades of wind drift) keep sub-millimetre precision.
double wrap01(double x, double period) {
  double f = std::fmod(x / period, 1.0);
  return f < 0.0 ? f + 1.0 : f;
}

glm::vec3 wrapped_offset(const glm::dvec3& world_m, double period) {
  return {static_cast<float>(wrap01(world_m.x, period)), static_cast<float>(wrap01(world_m.y, period)),
          static_cast<float>(wrap01(world_m.z, period))};
}

glm::vec4 to_vec4(const std::array<float, 4>& a) { return {a[0], a[1], a[2], a[3]}; }

}  // namespace

NoiseQuantiles noise_quantiles(const weather::NoiseVolume& v) {
  std::array<std::size_t, 256> hist{};
  for (std::uint8_t x : v.data) ++hist[x];
  NoiseQuantiles q{};
  const double n = static_cast<double>(v.data.size());
  std::size_t acc = 0;
  int value = 0;
  for (int i = 0; i < 16; ++i) {
    const double target = n * i / 15.0;
    while (value < 255 && static_cast<double>(acc + hist[static_cast<size_t>(value)]) < target) acc += hist[static_cast<size_t>(value++)];
    q[static_cast<size_t>(i)] = static_cast<float>(value) / 255.0f;
  }
  q[0] = 0.0f;
  q[15] = 1.0f;
  return q;
}

FrameUniforms pack_frame_uniforms(const FrameContext& c, const RenderQuality& quality,
                                  const GpuResourceSummary& resources) {
  FrameUniforms u{};
  u.enu_to_ecef = glm::mat4(glm::mat3(c.enu_to_ecef));
  u.camera_forward = glm::vec3(c.axes.forward);
  u.camera_right = glm::vec3(c.axes.right);
  u.camera_up = glm::vec3(c.axes.up);
  u.tan_half_fov_x = static_cast<float>(c.window.half_x);
  u.tan_half_fov_y = static_cast<float>(c.window.half_y);
  u.view_center_tan_x = static_cast<float>(c.window.center_x);
  u.view_center_tan_y = static_cast<float>(c.window.center_y);
  u.view_near_m = static_cast<float>(std::max(0.0, c.view.near_m));
  u.view_far_m = c.view.far_m > 0.0 ? static_cast<float>(c.view.far_m) : 1e30f;
  u.aerosol_scale = static_cast<float>(c.aerosol_scale);
  u.image_size_px = glm::vec2(static_cast<float>(c.view.width), static_cast<float>(c.view.height));
  // level of detail compares the angle one cloud pixel subtends with the noise texels
  u.pixel_angle_rad = static_cast<float>(2.0 * c.window.half_x / c.view.width *
                                         std::max(1, quality.cloud_resolution_divisor));

  u.shell_radius_m = static_cast<float>(c.shell_radius_m);
  u.camera_altitude_m = static_cast<float>(c.camera_altitude_m);
  u.ground_altitude_m = static_cast<float>(c.ground_altitude_m);
  u.march_reach_m = static_cast<float>(c.march_reach_m);
  u.sun_direction = glm::vec3(c.sun_enu);

  u.ap_max_distance_m = static_cast<float>(c.ap_max_distance_m());
  u.ap_forward = glm::vec3(c.ap.forward);
  u.ap_right = glm::vec3(c.ap.right);
  u.ap_up = glm::vec3(c.ap.up);
  u.ap_tan_half_width = static_cast<float>(c.ap.tan_half_width);
  u.ap_tan_half_height = static_cast<float>(c.ap.tan_half_height);

  u.primary_steps = quality.primary_steps;
  u.light_steps = quality.light_steps;
  u.ground_shadow_steps = quality.ground_shadow_steps;
  u.column_steps = std::max(0, quality.column_steps);
  u.sun_slab_tilt = quality.sun_slab_tilt && quality.column_steps > 0 ? 1 : 0;  // needs the columns' depths
  u.step_growth_ref_m = static_cast<float>(quality.step_growth_ref_m);
  u.long_step_factor = static_cast<float>(std::max(1, quality.long_step_factor));
  u.level_of_detail = quality.level_of_detail ? 1 : 0;
  u.detail_noise_mean = resources.detail_mean;
  u.base_noise_mean = resources.base_mean;
  // Light marches stop once the sun's beam is spent: past the cut-off for the peak beam,
  // which decays as e^(-w_D tau) (peak_beam_phase, shaders/phase_function.glsl).
  const double light_cut =
      quality.light_march_cutoff > 0.0 ? quality.light_march_cutoff / model::peak_beam_slowest_decay() : 1e30;
  u.light_march_cutoff_tau = static_cast<float>(std::min(light_cut, 1e30));
  u.coverage_pyramid = quality.coverage_pyramid && resources.coverage_pyramid ? 1 : 0;

  u.weather_map_height = static_cast<float>(resources.weather_map_height);
  u.weather_blend = resources.weather_blend;
  u.weather_pole_south = to_vec4(resources.weather_pole_south);
  u.weather_pole_north = to_vec4(resources.weather_pole_north);
  u.layer_coverage_pole_south = to_vec4(resources.layer_coverage_pole_south);
  u.layer_coverage_pole_north = to_vec4(resources.layer_coverage_pole_north);
  u.ground_albedo = glm::vec4(glm::vec3(c.ground_albedo), resources.ground_albedo_map ? 1.0f : 0.0f);
  u.ground_albedo_poles = to_vec4(resources.ground_albedo_poles);
  const NoiseQuantiles& q = resources.base_quantiles;
  for (int i = 0; i < 4; ++i) u.noise_quantiles[i] = glm::vec4(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);

  for (int i = 0; i < c.layer_count; ++i) {
    const LayerFrame& lf = c.layers[static_cast<size_t>(i)];
    const weather::CloudLayer& l = lf.layer;
    const weather::CloudTypeTraits& tr = weather::cloud_type_traits(l.type);
    const model::JdDParams ph = model::jdd_params(l.droplet_diameter_um);
    CloudLayerGpu& g = u.layers[i];
    g.base_m = static_cast<float>(l.base_m);
    g.top_m = static_cast<float>(l.top_m);
    g.coverage = static_cast<float>(lf.drawn_coverage());
    g.density_scale = static_cast<float>(l.density_scale);
    g.extinction_max = static_cast<float>(model::cloud_extinction_per_m(l.droplet_diameter_um));
    g.g_hg = static_cast<float>(ph.g_hg);
    g.g_d = static_cast<float>(ph.g_d);
    g.draine_alpha = static_cast<float>(ph.alpha);
    g.w_d = static_cast<float>(ph.w_d);
    g.base_noise_frequency = static_cast<float>(1.0 / lf.base_period_m);
    g.detail_noise_frequency = static_cast<float>(1.0 / lf.detail_period_m);
    g.detail_erosion = tr.profile.base_erosion;
    g.bottom_ramp = tr.profile.bottom_ramp;
    g.top_ramp = tr.profile.top_ramp;
    g.top_weight = tr.profile.top_weight;
    g.noise_vertical_scale = static_cast<float>(tr.noise_vertical_scale);
    // the camera's field position wrapped per period in double; the GPU adds rot * p
    g.base_noise_offset = wrapped_offset(lf.camera_field_m, lf.base_period_m);
    g.base_noise_cell = glm::ivec3(glm::floor(lf.camera_field_m / lf.base_period_m));
    g.detail_noise_cell = glm::ivec3(glm::floor(lf.camera_field_m / lf.detail_period_m));
    const std::uint32_t base_seed = weather::base_tiling_seed(resources.noise_seed, l.type);
    const std::uint32_t detail_seed = weather::detail_tiling_seed(resources.noise_seed, l.type);
    for (int k = 0; k < weather::kTilingLattices; ++k) {
      g.base_tiling_seeds[k] = weather::tiling_lattice_seed(base_seed, k);
      g.detail_tiling_seeds[k] = weather::tiling_lattice_seed(detail_seed, k);
    }
    g.stratiform = tr.stratiform ? 1 : 0;
    g.base_relief = static_cast<float>(tr.base_relief);
    g.detail_noise_offset = wrapped_offset(lf.camera_field_m, lf.detail_period_m);
    g.dome = lf.domes ? 1 : 0;
    g.anvil = glm::vec4(tr.anvil.spread, tr.anvil.base, tr.anvil.top, tr.anvil.density_ratio);
    g.noise_rotation = glm::mat4(glm::mat3(lf.noise_shaping * lf.field_rotation * c.enu_to_ecef));
    g.ms_similarity = static_cast<float>(model::ms_similarity_scale(ph));
    g.coverage_channel = l.coverage_channel;
    // the layer's full nominal optical depth tau_c of diffuse_inscatter (cloud_lighting.glsl)
    // (over the depth below the base raised by a textured base's mean lift: nominal_base_m)
    const double tau_cloud = static_cast<double>(g.extinction_max) * g.density_scale * (g.top_m - g.base_m) *
                             (1.0 - tr.base_relief * weather::kBaseLiftMean);
    static_assert(model::kSlabFluxMuNodes == 11, "ground_transmittance holds 11 beam values and the diffuse one");
    for (int j = 0; j < model::kSlabFluxMuNodes; ++j)
      g.ground_transmittance[j / 4][j % 4] =
          static_cast<float>(model::slab_beam_transmittance(tau_cloud, model::slab_flux_mu_node(j)));
    g.ground_transmittance[2][3] = static_cast<float>(model::slab_diffuse_transmittance(tau_cloud));
  }
  u.layer_count = c.layer_count;
  u.frame_index = static_cast<int>(c.view.frame_index % 65536u);
  u.count_density_evaluations = quality.count_density_evaluations ? 1 : 0;
  u.footprint_jitter = quality.footprint_jitter ? 1 : 0;
  return u;
}

}  // namespace cloudsvc
