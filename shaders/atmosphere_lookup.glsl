// Lookups into the atmosphere LUTs; needs atmosphere_model.glsl.
layout(binding = TEX_TRANSMITTANCE_LUT) uniform sampler2D transmittance_lut;   // 256x64, rgb transmittance to the top
layout(binding = TEX_MULTISCATTER_LUT) uniform sampler2D multiscatter_lut;    // 64x32 (mu_sun x alt), rgb log Psi_ms (Hillaire 2020 eq. 10)

// Transmittance from altitude alt along zenith cosine mu to space; 0 if the planet blocks it.
vec3 transmittance_to_space(float alt, float mu) {
  float r = atmo_radius(alt);
  if (ray_hits_ground(r, mu)) return vec3(0.0);
  return textureLod(transmittance_lut, transmittance_uv(r, mu, vec2(textureSize(transmittance_lut, 0))), 0.0).rgb;
}

// Lookup of a LUT over (sun_lut_u(mu_sun), alt / 100 km) that stores log values
// (atmosphere_model.glsl): log-linear along mu_sun (the filtered log of one altitude row,
// read at the row's texel centre, exponentiated), linear between the two altitude rows
// (over the uniform 3.2 km rows the log-linear form lost up to 3.5 dB of daytime accuracy,
// tests/accuracy_reference_vs_gpu_test.cpp, inside a stratus deck).
vec3 sun_lut_lookup(sampler2D lut, float alt, float mu_sun) {
  vec2 size = vec2(textureSize(lut, 0));
  float x = 0.5 / size.x + sun_lut_u(mu_sun) * (1.0 - 1.0 / size.x);
  float fy = saturate(alt / (ATMO_TOP - ATMO_BOTTOM)) * (size.y - 1.0);
  float y0 = min(floor(fy), size.y - 2.0);
  vec3 a = exp(textureLod(lut, vec2(x, (y0 + 0.5) / size.y), 0.0).rgb);
  vec3 b = exp(textureLod(lut, vec2(x, (y0 + 1.5) / size.y), 0.0).rgb);
  return mix(a, b, fy - y0);
}

// Multiple-scattering contribution Psi_ms for unit sun irradiance (sr^-1 per unit sigma_s).
// The LUT holds log Psi_ms over sun_lut_u(mu_sun) (atmosphere_model.glsl).
vec3 multiscatter(float alt, float mu_sun) {
  return sun_lut_lookup(multiscatter_lut, alt, mu_sun);
}

// In-scattered radiance per metre at a point (W m^-2 sr^-1 nm^-1 per m) for a unit-less
// sun irradiance; multiply by the solar irradiance. Single scattering with phase, plus
// Hillaire's isotropic multiple-scattering term.
vec3 atmo_inscatter_density(AtmoMedium m, float alt, float mu_sun, float cos_view_sun) {
  vec3 t_sun = transmittance_to_space(alt, mu_sun);
  vec3 single = (m.rayleigh * rayleigh_phase(cos_view_sun) + vec3(m.mie * aerosol_phase(cos_view_sun))) * t_sun;
  vec3 ms = (m.rayleigh + vec3(m.mie)) * multiscatter(alt, mu_sun);
  return single + ms;
}

// Ray march through the atmosphere from radius r (planet-centred frame with the start on
// the +z axis, so d and sun are in the start's local ENU frame) over distance len.
// Returns in-scattered radiance for unit solar irradiance (rgb) and the transmittance.
// Steps atmo_step_edge (30 uniform steps undersampled the aerosol layer by up to 10 % in
// the red below the sun; docs/ACCURACY.md).
void march_atmosphere(float r, vec3 d, vec3 sun, float len, int steps, out vec3 L, out vec3 T) {
  L = vec3(0.0);
  T = vec3(1.0);
  float nu = dot(d, sun);
  float p = atmo_step_power(len, steps, r, d.z);
  for (int i = 0; i < steps; ++i) {
    float t0 = atmo_step_edge(len, i, steps, p);
    float t1 = atmo_step_edge(len, i + 1, steps, p);
    float dt = t1 - t0;
    float t = 0.5 * (t0 + t1);
    vec3 x = vec3(0.0, 0.0, r) + t * d;
    float rx = length(x);
    float alt = rx - ATMO_BOTTOM;
    AtmoMedium m = atmo_medium(alt);
    vec3 S = atmo_inscatter_density(m, alt, dot(x, sun) / rx, nu);
    vec3 step_T = exp(-m.extinction * dt);
    L += T * S * (vec3(1.0) - step_T) / max(m.extinction, vec3(1e-12));
    T *= step_T;
  }
}

// Length of the atmospheric path from radius r along zenith cosine mu: to the ground or
// to the top of the atmosphere.
float atmosphere_path_length(float r, float mu) {
  return ray_hits_ground(r, mu) ? distance_to_bottom(r, mu) : distance_to_top(r, mu);
}

layout(binding = TEX_SKY_IRRADIANCE_LUT) uniform sampler2D sky_irradiance_lut;  // 64x32 (mu_sun x alt), rgb log E_sky for unit sun

// Sky irradiance on an upward-facing surface at altitude alt, unit sun irradiance. The LUT
// holds log E_sky over sun_lut_u(mu_sun) (atmosphere_model.glsl).
vec3 sky_irradiance(float alt, float mu_sun) {
  return sun_lut_lookup(sky_irradiance_lut, alt, mu_sun);
}
