#version 450 core
// Builds the light volume (light_volume.glsl) at the ground shadow map's anchor: texel
// (x, y, li * levels + k) holds layer li's optical depth towards the sun from the point at
// the texel's warped horizontal offset and level k's altitude, by the light march of
// cloud_lighting.glsl with frame.light_steps light steps (base shape only, as in the march).
#include "common.glsl"
#include "frame_counters.glsl"
#include "frame_uniforms.glsl"
#include "ground_shadow_map.glsl"
#include "light_volume.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "phase_function.glsl"
#include "weather_map_sampling.glsl"
#include "cloud_density.glsl"
#include "cloud_lighting.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = IMG_LIGHT_VOLUME_OUT) uniform writeonly image3D volume_out;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  int n = shadow.volume_texels, levels = shadow.volume_levels;
  int li = id.z / levels;
  if (id.x >= n || id.y >= n || li >= frame.layer_count) return;
  float alt = light_volume_altitude(li, float(id.z - li * levels));
  vec2 d = shadow_map_offset((vec2(id.xy) + 0.5) / float(n));
  float tau = 0.0;
  vec3 p;
  if (point_at_offset(d, alt, p)) {
    float mu_s = dot(up_at(p, frame.shell_radius_m, frame.camera_altitude_m), frame.sun_direction);
    float marched;  // the whole path: no cut-off, the volume is interpolated
    tau = light_optical_depth(li, p, alt, frame.sun_direction, mu_s, frame.light_steps, layer_weather_at(li, p), 1e30,
                              marched);
  }
  if (frame.count_density_evaluations != 0) atomicAdd(counters.density_evals, g_density_evals);
  imageStore(volume_out, id, vec4(tau));
  count_if_loops_capped();
}
