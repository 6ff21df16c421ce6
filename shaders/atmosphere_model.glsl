// Earth atmosphere in the style of Hillaire 2020, "A Scalable and Production Ready Sky
// and Atmosphere Rendering Technique" (EGSR). Its constants (ATMO_BOTTOM, ATMO_TOP,
// RAYLEIGH_*, MIE_*, OZONE_ABSORPTION) come from renderer/model/atmosphere_constants.h
// through the preamble of renderer/gpu_interface.cpp; the aerosol's amount is scaled by
// frame.aerosol_scale (the weather's visibility), so frame_uniforms.glsl comes first.
// Lengths in metres, coefficients in 1/m. The atmosphere is spherically symmetric: only the
// altitude and the zenith cosine of a ray matter, so it uses its own radius (6360 km)
// regardless of the cloud-shell radius.

struct AtmoMedium {
  vec3 rayleigh;   // scattering, 1/m
  float mie;       // scattering, 1/m
  vec3 extinction; // total, 1/m
};

AtmoMedium atmo_medium(float alt) {
  alt = max(alt, 0.0);
  float dr = exp(-alt / RAYLEIGH_SCALE_HEIGHT);
  float dm = exp(-alt / MIE_SCALE_HEIGHT);
  float doz = max(0.0, 1.0 - abs(alt - 25.0e3) / 15.0e3);  // tent 10-25-40 km
  AtmoMedium m;
  m.rayleigh = RAYLEIGH_SCATTERING * dr;
  dm *= frame.aerosol_scale;
  m.mie = MIE_SCATTERING * dm;
  m.extinction = m.rayleigh + vec3(MIE_EXTINCTION * dm) + OZONE_ABSORPTION * doz;
  return m;
}

// Steps along a ray of length len from radius r with zenith cosine mu: n steps with edges
// t_i = len (i / n)^p (atmo_step_edge), p once per ray (atmo_step_power). Rays that climb meet their densest air (the aerosol, H = 1.2 km) at
// the start, so p = 1 + mu: up to quadratic towards the zenith, uniform for horizontal and
// descending rays, whose air stays dense over most of the path. And the first step holds
// at most one optical depth of the air at the start (p >= ln(len sigma_t) / ln n): in haze
// (frame.aerosol_scale; 3 km visibility, sigma_t = 1e-3 / m) a horizontal ray from the
// ground would otherwise take its 1100 km in steps of 37 km, each far beyond where its
// light comes from. The default air (sigma_t 1.8e-5 / m at the ground) hardly needs it: at
// most p = 1.08, for near-horizontal rays of the 16-step sky-irradiance march.
float atmo_step_power(float len, int n, float r, float mu) {
  float sigma = atmo_medium(r - ATMO_BOTTOM).extinction.g;
  return max(1.0 + max(mu, 0.0), log(max(len * sigma, 1.0)) / log(float(n)));
}
float atmo_step_edge(float len, int i, int n, float p) {
  return len * pow(float(i) / float(n), p);
}

float rayleigh_phase(float mu) { return 3.0 / (16.0 * PI) * (1.0 + mu * mu); }

// Cornette-Shanks phase for the aerosol (Mie) component, sr^-1.
float aerosol_phase(float mu) {
  float g = MIE_G, g2 = g * g;
  float k = 3.0 / (8.0 * PI) * (1.0 - g2) / (2.0 + g2);
  return k * (1.0 + mu * mu) / pow(max(1.0 + g2 - 2.0 * g * mu, 1e-6), 1.5);
}

// Distance from radius r along zenith cosine mu to the top / bottom sphere.
float distance_to_top(float r, float mu) {
  float disc = r * r * (mu * mu - 1.0) + ATMO_TOP * ATMO_TOP;
  return max(0.0, -r * mu + sqrt(max(disc, 0.0)));
}
float distance_to_bottom(float r, float mu) {
  float disc = r * r * (mu * mu - 1.0) + ATMO_BOTTOM * ATMO_BOTTOM;
  return max(0.0, -r * mu - sqrt(max(disc, 0.0)));
}
bool ray_hits_ground(float r, float mu) {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + ATMO_BOTTOM * ATMO_BOTTOM >= 0.0;
}

// Transmittance LUT parameterisation (Bruneton 2017, §"Transmittance"): x_r from the
// horizon distance, x_mu from the distance to the top, both in [0, 1].
vec2 transmittance_uv(float r, float mu, vec2 size) {
  float H = sqrt(ATMO_TOP * ATMO_TOP - ATMO_BOTTOM * ATMO_BOTTOM);
  float rho = sqrt(max(r * r - ATMO_BOTTOM * ATMO_BOTTOM, 0.0));
  float d = distance_to_top(r, mu);
  float d_min = ATMO_TOP - r, d_max = rho + H;
  float x_mu = (d_max > d_min) ? (d - d_min) / (d_max - d_min) : 0.0;
  float x_r = rho / H;
  // texel-centre mapping
  return vec2(0.5 / size.x + x_mu * (1.0 - 1.0 / size.x), 0.5 / size.y + x_r * (1.0 - 1.0 / size.y));
}
vec2 transmittance_r_mu(vec2 uv, vec2 size) {
  float x_mu = saturate((uv.x - 0.5 / size.x) / (1.0 - 1.0 / size.x));
  float x_r = saturate((uv.y - 0.5 / size.y) / (1.0 - 1.0 / size.y));
  float H = sqrt(ATMO_TOP * ATMO_TOP - ATMO_BOTTOM * ATMO_BOTTOM);
  float rho = H * x_r;
  float r = sqrt(rho * rho + ATMO_BOTTOM * ATMO_BOTTOM);
  float d_min = ATMO_TOP - r, d_max = rho + H;
  float d = d_min + x_mu * (d_max - d_min);
  float mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
  return vec2(r, clamp(mu, -1.0, 1.0));
}

// Radius used for atmosphere lookups of a point at altitude alt (m) above the shell.
float atmo_radius(float alt) { return clamp(ATMO_BOTTOM + alt, ATMO_BOTTOM + 1.0, ATMO_TOP - 1.0); }

// Sun-zenith-cosine axis of the multiple-scattering and sky-irradiance LUTs (u in [0, 1]
// over their width): mu_sun = 0.25 x + 0.75 x^3 with x = 2u - 1, the mapping of the CPU
// reference's tables (renderer/reference/atmosphere_tables.cpp, MuAltitudeTable): nodes
// 10x denser at the horizon (d mu / dx = 0.25) than at the zenith (2.5), where twilight
// Psi_ms and E_sky fall by orders of magnitude over a few degrees. Both LUTs store
// log(max(value, SUN_LUT_FLOOR)), interpolated log-linearly along mu_sun
// (sun_lut_lookup, atmosphere_lookup.glsl): linear interpolation of such a steep function
// between the former 32 uniform nodes made twilight skies and clouds 2-5x too bright
// (sun at -7 deg; tests/twilight_reference_vs_gpu_test.cpp).
const float SUN_LUT_FLOOR = 1e-30;
float sun_lut_mu(float u) {
  float x = 2.0 * u - 1.0;
  return 0.25 * x + 0.75 * x * x * x;
}
// Inverse of sun_lut_mu: the real root of x^3 + x/3 - 4 mu/3 = 0 (Cardano's formula;
// the discriminant (2 mu / 3)^2 + (1/9)^3 is positive, so there is one real root).
float sun_lut_u(float mu) {
  float a = 2.0 * clamp(mu, -1.0, 1.0) / 3.0;
  float s = sqrt(a * a + 1.0 / 729.0);
  float p = a + s, q = a - s;
  float x = sign(p) * pow(abs(p), 1.0 / 3.0) + sign(q) * pow(abs(q), 1.0 / 3.0);
  return saturate(0.5 * x + 0.5);
}
