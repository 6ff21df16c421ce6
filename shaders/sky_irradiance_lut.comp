#version 450 core
// Sky irradiance LUT E_sky(alt, mu_sun): irradiance on an upward-facing horizontal
// surface from the whole sky dome (direct sun excluded), for unit solar irradiance.
// Integrated from the same single + multiple scattering model as the sky (64 cosine-
// weighted directions: E = pi * mean(L)). Stored as log E_sky; u = sun_lut_u(mu_sun)
// (atmosphere_model.glsl), v = alt / 100 km.
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = IMG_LUT_OUT) uniform writeonly image2D out_lut;

const int DIRS = 64;
const int STEPS = 16;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(out_lut);
  if (any(greaterThanEqual(px, size))) return;
  vec2 uv = vec2(px) / vec2(size - 1);
  float mu_sun = sun_lut_mu(uv.x);
  float r = atmo_radius(uv.y * (ATMO_TOP - ATMO_BOTTOM));
  vec3 sun = vec3(sqrt(max(0.0, 1.0 - mu_sun * mu_sun)), 0.0, mu_sun);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < DIRS; ++k) {
    // cosine-weighted hemisphere via a Fibonacci lattice on the unit disc
    float rad = sqrt((float(k) + 0.5) / float(DIRS));
    float phi = float(k) * 2.39996322972865;
    vec3 d = vec3(rad * cos(phi), rad * sin(phi), sqrt(max(0.0, 1.0 - rad * rad)));
    vec3 L, T;
    march_atmosphere(r, d, sun, atmosphere_path_length(r, d.z), STEPS, L, T);
    sum += L;
  }
  imageStore(out_lut, px, vec4(log(max(PI * sum / float(DIRS), vec3(SUN_LUT_FLOOR))), 1.0));
}
