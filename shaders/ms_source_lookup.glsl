// The sun's multiple-scattering source table on the GPU (renderer/ms_source_texture.h):
// the lookup of model::MsSourceTable::lookup (renderer/model/ms_source_table.h) over the
// table's 3-D texture. Needs common.glsl and the MS_* constants of the interface preamble.
// J_d / mu_s: the sun's light scattered at least once through the droplets' Draine lobe
// and scattered again, per unit horizontal solar flux and unit scattering (sr^-1), from
// Monte Carlo in conservative slabs.
layout(binding = TEX_MS_SOURCE) uniform sampler3D ms_source_table;

// ln(1 + x) for x >= 0 without the float round-off of 1 + x below x ~ 1e-3.
float log1p_pos(float x) { return x < 1e-3 ? x * (1.0 - 0.5 * x) : log(1.0 + x); }

// ms_depth_coordinate (renderer/model/ms_source_table.cpp): log-spaced from the top and the
// base towards the middle of the slab, 0 at the top, 1 at the base.
float ms_depth_coordinate(float tau_a, float tau_b) {
  float h = 0.5 * (tau_a + tau_b);
  if (h <= 1e-12) return 0.5;
  float den = 2.0 * log1p_pos(h / MS_DEPTH_SCALE);
  return tau_a <= tau_b ? log1p_pos(tau_a / MS_DEPTH_SCALE) / den : 1.0 - log1p_pos(tau_b / MS_DEPTH_SCALE) / den;
}

// MsSourceTable::lookup: tau_a, tau_b the optical depths above and below the point (scaled
// to the table's droplets), mu_s the sun's zenith cosine, mu_w and phi_deg the zenith
// cosine and relative azimuth (0..180) of the scattered light's travel direction.
// Linear in log2 tau and the sun's zenith angle over four texture blocks, trilinear
// within each by the texture unit; thinner slabs than the table's first node scale with tau.
float ms_source_over_mu(float tau_a, float tau_b, float mu_s, float mu_w, float phi_deg) {
  float tau = tau_a + tau_b;
  if (!(tau > 0.0)) return 0.0;
  float thin = min(tau / MS_TAU_MIN, 1.0);
  float ct = clamp(log2(max(tau, MS_TAU_MIN) / MS_TAU_MIN), 0.0, float(MS_TAU_NODES - 1));
  float cs = clamp(degrees(acos(clamp(mu_s, 0.0, 1.0))) * (float(MS_SUN_NODES - 1) / MS_SUN_ZENITH_MAX_DEG), 0.0,
                   float(MS_SUN_NODES - 1));
  int t0 = min(int(ct), MS_TAU_NODES - 2), s0 = min(int(cs), MS_SUN_NODES - 2);
  float ft = ct - float(t0), fs = cs - float(s0);
  float u = (clamp(phi_deg, 0.0, 180.0) * (float(MS_PHI_NODES - 1) / 180.0) + 0.5) / float(MS_PHI_NODES);
  float v = ((clamp(mu_w, -1.0, 1.0) + 1.0) * 0.5 * float(MS_MU_NODES - 1) + 0.5) / float(MS_MU_NODES);
  float zy = clamp(ms_depth_coordinate(tau_a, tau_b) * float(MS_DEPTH_BINS), 0.5, float(MS_DEPTH_BINS) - 0.5);
  const float depth = float(MS_DEPTH_BINS * MS_SUN_NODES * MS_TAU_NODES);
  float b00 = float(MS_DEPTH_BINS * (s0 + MS_SUN_NODES * t0));
  const float sun_step = float(MS_DEPTH_BINS), tau_step = float(MS_DEPTH_BINS * MS_SUN_NODES);
  float j00 = texture(ms_source_table, vec3(u, v, (b00 + zy) / depth)).r;
  float j01 = texture(ms_source_table, vec3(u, v, (b00 + sun_step + zy) / depth)).r;
  float j10 = texture(ms_source_table, vec3(u, v, (b00 + tau_step + zy) / depth)).r;
  float j11 = texture(ms_source_table, vec3(u, v, (b00 + tau_step + sun_step + zy) / depth)).r;
  return thin * max(mix(mix(j00, j01, fs), mix(j10, j11, fs), ft), 0.0);
}

