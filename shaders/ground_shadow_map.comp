#version 450 core
// Builds the ground shadow map (ground_shadow_map.glsl) for the current frame, which is the
// anchor: texel (x, y) of array layer li holds layer li's optical depth towards the sun
// above the ground point at the texel's offset (0 where the sun is down).
#include "common.glsl"
#include "frame_counters.glsl"
#include "frame_uniforms.glsl"
#include "ground_shadow_map.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "phase_function.glsl"
#include "weather_map_sampling.glsl"
#include "cloud_density.glsl"
#include "cloud_lighting.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = IMG_SHADOW_MAP_OUT) uniform writeonly image2DArray shadow_map;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  int n = shadow.map_texels;
  if (id.x >= n || id.y >= n || id.z >= frame.layer_count) return;
  vec2 d = shadow_map_offset((vec2(id.xy) + 0.5) / float(n));
  float R = frame.shell_radius_m, h = frame.camera_altitude_m, g = frame.ground_altitude_m;
  float tau = 0.0;
  vec3 p;  // the ground point under offset d
  if (point_at_offset(d, g, p)) {
    float mu_s = dot(up_at(p, R, h), frame.sun_direction);
    if (mu_s > 0.0) tau = layer_shadow_optical_depth(id.z, p, g, frame.sun_direction, mu_s, frame.ground_shadow_steps);
  }
  if (frame.count_density_evaluations != 0) atomicAdd(counters.density_evals, g_density_evals);
  imageStore(shadow_map, id, vec4(tau));
  count_if_loops_capped();
}
