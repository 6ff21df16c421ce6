#version 450 core
// Transmittance to the top of the atmosphere, T(r, mu) (Hillaire 2020 §4; Bruneton 2017).
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "atmosphere_model.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = IMG_LUT_OUT) uniform writeonly image2D out_lut;

const int STEPS = 40;  // atmo_step_edge (uniform steps missed 27 % of a hazy vertical path's aerosol)

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(out_lut);
  if (any(greaterThanEqual(px, size))) return;
  vec2 rmu = transmittance_r_mu((vec2(px) + 0.5) / vec2(size), vec2(size));
  float r = rmu.x, mu = rmu.y;
  float len = distance_to_top(r, mu);
  float p = atmo_step_power(len, STEPS, r, mu);
  vec3 tau = vec3(0.0);
  for (int i = 0; i < STEPS; ++i) {
    float t0 = atmo_step_edge(len, i, STEPS, p), t1 = atmo_step_edge(len, i + 1, STEPS, p);
    float t = 0.5 * (t0 + t1), dt = t1 - t0;
    float ri = sqrt(r * r + t * t + 2.0 * r * mu * t);
    tau += atmo_medium(ri - ATMO_BOTTOM).extinction * dt;
  }
  imageStore(out_lut, px, vec4(exp(-tau), 1.0));
}
