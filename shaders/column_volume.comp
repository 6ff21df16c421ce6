#version 450 core
// Builds the column volume (column_volume.glsl) at the ground shadow map's anchor: one
// invocation per texel column (x, y) and layer li integrates the layer's radial line at the
// texel's warped horizontal offset from its base to its top with the marched columns'
// quadrature (column_quadrature.glsl: base shape only, read at the steps' ends and linear
// between them, the coverage threshold's ramp integrated exactly), in ceil(column_steps /
// COLUMN_VOLUME_LEVELS) steps per level between the (cosine-spaced) altitude nodes, the
// column's weather map value read once (the line is vertical), and stores at every node the optical depth
// accumulated below it and the rest of the column's above it.
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
#include "column_quadrature.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rg16f, binding = IMG_COLUMN_VOLUME_OUT) uniform writeonly image3D volume_out;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  int li = id.z;
  if (id.x >= COLUMN_VOLUME_TEXELS || id.y >= COLUMN_VOLUME_TEXELS || li >= frame.layer_count) return;
  CloudLayerGpu L = frame.layers[li];
  float base = L.base_m, H = L.top_m - L.base_m;
  vec2 d = shadow_map_offset((vec2(id.xy) + 0.5) / float(COLUMN_VOLUME_TEXELS));
  float below[COLUMN_VOLUME_NODES];
  for (int k = 0; k < COLUMN_VOLUME_NODES; ++k) below[k] = 0.0;
  vec3 foot;  // the column's foot: the point at offset d and the layer's base
  if (point_at_offset(d, base, foot) && L.coverage > 0.0) {
    vec3 up = up_at(foot, frame.shell_radius_m, frame.camera_altitude_m);
    vec4 w = layer_weather_at(li, foot);
    // steps per level: the column's nodes are the steps' ends
    int m = max((frame.column_steps + COLUMN_VOLUME_LEVELS - 1) / COLUMN_VOLUME_LEVELS, 1);
#ifdef CLOUDSVC_CUMULUS_DOMES
    if (L.dome != 0) {
      float z0 = 0.0;
      for (int k = 1; k < COLUMN_VOLUME_NODES; ++k) {
        float z1 = H * column_node_fraction(float(k) / float(COLUMN_VOLUME_LEVELS));
        below[k] = below[k - 1] + dome_column_part(li, foot + up * z0, base + z0, up, w, z1 - z0, m, 0.5);
        z0 = z1;
      }
    } else
#endif
    {
      ColumnThreshold c = column_threshold(L, w);
      if (c.coverage > 0.0) {
        int n = m * COLUMN_VOLUME_LEVELS;
        g_density_evals += 1u;
        float shape0 = base_shape_at(L, field_point(L, foot, base));
        float g0 = column_g(L, c, shape0, 0.0);
        float fraction = 0.0, scale = extinction_scale(L, w) * H, t0 = 0.0;
        for (int j = 1; j <= n; ++j) {
          float t1 = column_node_fraction(float(j) / float(n));
          g_density_evals += 1u;
          float shape1 = base_shape_at(L, field_point(L, foot + up * (t1 * H), base + t1 * H));
          fraction += column_step(L, base, c, shape0, shape1, g0, t0, t1, H, column_step_pieces(L, (t1 - t0) * H));
          shape0 = shape1;
          t0 = t1;
          if (j % m == 0) below[j / m] = fraction * scale;
        }
      }
    }
  }
  float total = below[COLUMN_VOLUME_NODES - 1];
  if (frame.count_density_evaluations != 0) atomicAdd(counters.density_evals, g_density_evals);
  for (int k = 0; k < COLUMN_VOLUME_NODES; ++k)
    imageStore(volume_out, ivec3(id.xy, li * COLUMN_VOLUME_NODES + k), vec4(below[k], max(total - below[k], 0.0), 0.0, 0.0));
  count_if_loops_capped();
}
