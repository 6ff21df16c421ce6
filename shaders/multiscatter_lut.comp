#version 450 core
// Multiple-scattering LUT Psi_ms(alt, mu_sun) of Hillaire 2020 §5.5 (eqs. 5-10): second-
// order luminance L_2nd and transfer f_ms from 64 directions with isotropic phase, then
// Psi_ms = L_2nd / (1 - f_ms). Unit sun irradiance. Stored as log Psi_ms over
// u = sun_lut_u(mu_sun) (atmosphere_model.glsl).
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "atmosphere_model.glsl"
layout(binding = TEX_TRANSMITTANCE_LUT) uniform sampler2D transmittance_lut;

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = IMG_LUT_OUT) uniform writeonly image2D out_lut;

const int DIRS = 64;
const int STEPS = 20;  // atmo_step_edge (uniform steps missed the haze near the ground)

vec3 sun_transmittance(float r, float mu) {
  if (ray_hits_ground(r, mu)) return vec3(0.0);
  return textureLod(transmittance_lut, transmittance_uv(r, mu, vec2(textureSize(transmittance_lut, 0))), 0.0).rgb;
}

// Spherical Fibonacci direction i of n (uniform on the sphere).
vec3 fibonacci_dir(int i, int n) {
  float z = 1.0 - (2.0 * float(i) + 1.0) / float(n);
  float phi = float(i) * 2.39996322972865;  // golden angle
  float s = sqrt(max(0.0, 1.0 - z * z));
  return vec3(s * cos(phi), s * sin(phi), z);
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(out_lut);
  if (any(greaterThanEqual(px, size))) return;
  // Unit parameters at px / (n - 1): multiscatter() in atmosphere_lookup.glsl reads
  // texel centres with the same mapping (mu_sun through sun_lut_mu, atmosphere_model.glsl).
  vec2 uv = vec2(px) / vec2(size - 1);
  float mu_sun = sun_lut_mu(uv.x);
  float r = ATMO_BOTTOM + clamp(uv.y * (ATMO_TOP - ATMO_BOTTOM), 1.0, ATMO_TOP - ATMO_BOTTOM - 1.0);
  vec3 sun = vec3(sqrt(max(0.0, 1.0 - mu_sun * mu_sun)), 0.0, mu_sun);

  vec3 L2 = vec3(0.0), fms = vec3(0.0);
  for (int k = 0; k < DIRS; ++k) {
    vec3 d = fibonacci_dir(k, DIRS);
    float mu = d.z;
    bool ground = ray_hits_ground(r, mu);
    float len = ground ? distance_to_bottom(r, mu) : distance_to_top(r, mu);
    float p = atmo_step_power(len, STEPS, r, mu);
    vec3 T = vec3(1.0), L = vec3(0.0), F = vec3(0.0);
    for (int i = 0; i < STEPS; ++i) {
      float t0 = atmo_step_edge(len, i, STEPS, p), t1 = atmo_step_edge(len, i + 1, STEPS, p);
      float t = 0.5 * (t0 + t1), dt = t1 - t0;
      vec3 x = vec3(0.0, 0.0, r) + t * d;
      float rx = length(x);
      AtmoMedium m = atmo_medium(rx - ATMO_BOTTOM);
      vec3 sigma_s = m.rayleigh + vec3(m.mie);
      vec3 Ts = sun_transmittance(rx, dot(x, sun) / rx);
      vec3 step_T = exp(-m.extinction * dt);
      // energy-conserving integral of S over the step: S (1 - e^{-sigma_t dt}) / sigma_t
      vec3 w = (vec3(1.0) - step_T) / max(m.extinction, vec3(1e-12));
      L += T * w * sigma_s * Ts * INV_4PI;
      F += T * w * sigma_s;
      T *= step_T;
    }
    if (ground) {
      vec3 x = vec3(0.0, 0.0, r) + len * d;
      float mu_g = dot(normalize(x), sun);
      L += T * sun_transmittance(ATMO_BOTTOM, mu_g) * max(mu_g, 0.0) * GROUND_ALBEDO / PI;
    }
    L2 += L;             // L' (already includes p_u for the sun scatter)
    fms += F * INV_4PI;  // L_f p_u
  }
  // Integrals over the sphere with the isotropic phase p_u = 1/(4 pi): each direction
  // carries 4 pi / DIRS sr, so  L_2nd = sum(L'_k) / DIRS  and  f_ms = sum(L_f,k) / DIRS.
  L2 /= float(DIRS);
  fms *= 4.0 * PI / float(DIRS);
  vec3 psi = L2 / max(vec3(1.0) - fms, vec3(1e-3));
  imageStore(out_lut, px, vec4(log(max(psi, vec3(SUN_LUT_FLOOR))), 1.0));  // log: see sun_lut_mu
}
