#version 450 core
// Builds the column volume (column_volume.glsl) at the ground shadow map's anchor: one
// invocation per texel column (x, y) and layer li marches the layer's radial line at the
// texel's warped horizontal offset from its base to its top in frame.column_steps equal
// steps (midpoint rule, base shape only as in the light march, the column's weather map
// value read once: the line is vertical), and stores at every altitude node the optical
// depth accumulated below it and the rest of the column's above it.
#include "common.glsl"
#include "frame_counters.glsl"
#include "frame_uniforms.glsl"
#include "ground_shadow_map.glsl"
#include "column_volume.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "phase_function.glsl"
#include "weather_map_sampling.glsl"
#include "cloud_density.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rg16f, binding = IMG_COLUMN_VOLUME_OUT) uniform writeonly image3D volume_out;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  int li = id.z;
  if (id.x >= COLUMN_VOLUME_TEXELS || id.y >= COLUMN_VOLUME_TEXELS || li >= frame.layer_count) return;
  float base = frame.layers[li].base_m, top = frame.layers[li].top_m;
  vec2 d = shadow_map_offset((vec2(id.xy) + 0.5) / float(COLUMN_VOLUME_TEXELS));
  float below[COLUMN_VOLUME_NODES];
  for (int k = 0; k < COLUMN_VOLUME_NODES; ++k) below[k] = 0.0;
  float total = 0.0;
  vec3 foot;  // the column's foot: the point at offset d and the layer's base
  if (point_at_offset(d, base, foot) && frame.layers[li].coverage > 0.0) {
    vec3 up = up_at(foot, frame.shell_radius_m, frame.camera_altitude_m);
    vec4 w = layer_weather_at(li, foot);
    int n = max(frame.column_steps, 1);
    float H = top - base, dz = H / float(n), node_dz = H / float(COLUMN_VOLUME_LEVELS);
    int k = 1;  // the next node above the foot
    // one sample per step at the same place in every step of a column, a different place in
    // each column (stratified: no column's samples all fall in the same part of the domes'
    // vertical structure)
    float u = hash12(uvec2(id.x + id.y * COLUMN_VOLUME_TEXELS, li));
    for (int j = 0; j < n; ++j) {
      float s0 = float(j) * dz;
      float coverage;
      // the line is radial: the altitude of a point s above the foot is base + s
      float sigma = cloud_extinction_in(li, foot + up * (s0 + u * dz), base + s0 + u * dz, DETAIL_NONE, w, coverage);
      // nodes inside this step get the depth up to them
      for (; k < COLUMN_VOLUME_NODES && float(k) * node_dz <= s0 + dz * 1.0001; ++k)
        below[k] = total + sigma * (float(k) * node_dz - s0);
      total += sigma * dz;
    }
    for (; k < COLUMN_VOLUME_NODES; ++k) below[k] = total;
  }
  if (frame.count_density_evaluations != 0) atomicAdd(counters.density_evals, g_density_evals);
  for (int k = 0; k < COLUMN_VOLUME_NODES; ++k)
    imageStore(volume_out, ivec3(id.xy, li * COLUMN_VOLUME_NODES + k), vec4(below[k], max(total - below[k], 0.0), 0.0, 0.0));
  count_if_loops_capped();
}
