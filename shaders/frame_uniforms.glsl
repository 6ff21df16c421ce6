// Per-frame constants, std140: the GLSL side of renderer/frame_uniforms.h (member
// comments, units and frames there; tests/gpu_interface_test.cpp checks that both sides
// agree). Frame: "local" = East-North-Up axes at the camera, origin at the camera,
// metres. The cloud shell and ground are spheres of radius shell_radius_m (the osculating
// sphere of the WGS84 ellipsoid at the camera) centred at (0, 0, -(R + h)).

struct CloudLayerGpu {
  float base_m, top_m, coverage, density_scale;
  float extinction_max, g_hg, g_d, draine_alpha;
  float w_d, base_noise_frequency, detail_noise_frequency, detail_erosion;
  float bottom_ramp, top_ramp, top_weight, noise_vertical_scale;
  vec3 base_noise_offset;
  int stratiform;
  vec3 detail_noise_offset;
  int dome;    // 1: individual cumulus domes (cumulus_domes.glsl; dome slot = layer index)
  vec4 anvil;  // weather::Anvil: spread (0: none), base, top, density_ratio
  mat4 noise_rotation;
  float ms_similarity;  // model::ms_similarity_scale: optical depths onto the source table's droplets
  int coverage_channel;  // weather::CloudLayer::coverage_channel: -1 R-modulated, 0-3 a layer-coverage channel
  float base_relief;  // weather::CloudTypeTraits::base_relief: the base rises by up to this fraction of the depth
  // the noises' stochastic tiling (noise_tiling.glsl): floor(camera's field position /
  // period) and the four lattices' hash seeds (weather::tiling_lattice_seed)
  ivec3 base_noise_cell;
  ivec3 detail_noise_cell;
  uvec4 base_tiling_seeds;
  uvec4 detail_tiling_seeds;
  // the slab transmittance of the layer's full nominal optical depth: [j / 4][j % 4] for the
  // sun's beam at the table's zenith cosine j (< SLAB_FLUX_MU_NODES), [2].w for diffuse light
  vec4 ground_transmittance[3];
};

layout(std140, binding = UBO_FRAME) uniform FrameUniforms {
  mat4 enu_to_ecef;
  vec3 camera_forward;
  float tan_half_fov_x;
  vec3 camera_right;
  float tan_half_fov_y;
  vec3 camera_up;
  float pixel_angle_rad;
  vec3 sun_direction;
  float weather_blend;
  vec3 ap_forward;
  float ap_max_distance_m;
  vec3 ap_right;
  float ap_tan_half_width;
  vec3 ap_up;
  float ap_tan_half_height;
  vec2 image_size_px;
  float shell_radius_m;
  float camera_altitude_m;
  float ground_altitude_m;
  float march_reach_m;
  float weather_map_height;
  float step_growth_ref_m;
  int primary_steps, light_steps, ground_shadow_steps;
  float light_march_cutoff_tau;
  float long_step_factor;
  float detail_noise_mean;
  float base_noise_mean;  // noise_tiling.glsl's blend
  int level_of_detail;
  int coverage_pyramid;
  int layer_count;
  int frame_index;
  int count_density_evaluations;
  int footprint_jitter;
  float view_center_tan_x;
  float view_center_tan_y;
  float view_near_m;  // clouds drawn between the near and far planes (cloud_clip)
  float view_far_m;
  float aerosol_scale;  // on MIE_SCATTERING and MIE_EXTINCTION (the weather's visibility)
  int column_steps;     // steps of each column of the column volume (column_volume.comp)
  int sun_slab_tilt;    // 1: the sun's diffuse source from the tilted slab (tilted_sun_slab)
  vec4 noise_quantiles[4];
  vec4 weather_pole_south;
  vec4 weather_pole_north;
  vec4 layer_coverage_pole_south;  // the map's layer-coverage channels at the poles (row means)
  vec4 layer_coverage_pole_north;
  vec4 ground_albedo;        // rgb; w 1: an albedo map (ground_albedo_at)
  vec4 ground_albedo_poles;  // the albedo map's (R, G) at the south pole, then the north's
  CloudLayerGpu layers[MAX_LAYERS];
} frame;

// A point p of the local frame as seen from the shell centre, in ECEF axes (m).
vec3 from_shell_centre(vec3 p) {
  return mat3(frame.enu_to_ecef) * (p + vec3(0.0, 0.0, frame.shell_radius_m + frame.camera_altitude_m));
}
