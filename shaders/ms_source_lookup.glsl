// The multiple-scattering source tables on the GPU (renderer/ms_source_textures.h): the
// lookups of model::MsSourceTable::lookup (renderer/model/ms_source_table.h) over the
// tables' 3-D textures. Needs common.glsl and the MS_* constants of the interface preamble.
// Both are from Monte Carlo in conservative slabs, per unit scattering (sr^-1):
// * the sun's, J_d / mu_s: the sun's light scattered at least once through the droplets'
//   Draine lobe and scattered again, per unit horizontal solar flux;
// * the diffuse light's, J: diffuse (Lambertian) light entering through the slab's top,
//   every order, per unit incident horizontal flux (model::ms_diffuse_incidence_table).
layout(binding = TEX_MS_SOURCE) uniform sampler3D ms_source_table;
layout(binding = TEX_MS_DIFFUSE_INCIDENCE) uniform sampler3D ms_diffuse_incidence_table;

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

// The optical-depth axis shared by both tables: node t0 and weight ft of the slab's total
// optical depth tau > 0 (log2-spaced from MS_TAU_MIN), and the thin-slab scale (J ~ tau
// below the first node).
void ms_tau_axis(float tau, out int t0, out float ft, out float thin) {
  thin = min(tau / MS_TAU_MIN, 1.0);
  float ct = clamp(log2(max(tau, MS_TAU_MIN) / MS_TAU_MIN), 0.0, float(MS_TAU_NODES - 1));
  t0 = min(int(ct), MS_TAU_NODES - 2);
  ft = ct - float(t0);
}

// The texture coordinate of the scattered light's zenith cosine mu_w (y, both tables).
float ms_mu_texcoord(float mu_w) {
  return ((clamp(mu_w, -1.0, 1.0) + 1.0) * 0.5 * float(MS_MU_NODES - 1) + 0.5) / float(MS_MU_NODES);
}

// The depth in texels within a block, kept between its first and last bin centres.
float ms_depth_texel(float tau_a, float tau_b) {
  return clamp(ms_depth_coordinate(tau_a, tau_b) * float(MS_DEPTH_BINS), 0.5, float(MS_DEPTH_BINS) - 0.5);
}

// MsSourceTable::lookup of the sun's table: tau_a, tau_b the optical depths above and below
// the point (scaled to the table's droplets), mu_s the sun's zenith cosine, mu_w and
// phi_deg the zenith cosine and relative azimuth (0..180) of the scattered light's travel
// direction. Linear in log2 tau and the sun's zenith angle over four texture blocks,
// trilinear within each by the texture unit.
float ms_source_over_mu(float tau_a, float tau_b, float mu_s, float mu_w, float phi_deg) {
  float tau = tau_a + tau_b;
  if (!(tau > 0.0)) return 0.0;
  int t0;
  float ft, thin;
  ms_tau_axis(tau, t0, ft, thin);
  float cs = clamp(degrees(acos(clamp(mu_s, 0.0, 1.0))) * (float(MS_SUN_NODES - 1) / MS_SUN_ZENITH_MAX_DEG), 0.0,
                   float(MS_SUN_NODES - 1));
  int s0 = min(int(cs), MS_SUN_NODES - 2);
  float fs = cs - float(s0);
  float u = (clamp(phi_deg, 0.0, 180.0) * (float(MS_PHI_NODES - 1) / 180.0) + 0.5) / float(MS_PHI_NODES);
  float v = ms_mu_texcoord(mu_w);
  float zy = ms_depth_texel(tau_a, tau_b);
  const float depth = float(MS_DEPTH_BINS * MS_SUN_NODES * MS_TAU_NODES);
  float b00 = float(MS_DEPTH_BINS * (s0 + MS_SUN_NODES * t0));
  const float sun_step = float(MS_DEPTH_BINS), tau_step = float(MS_DEPTH_BINS * MS_SUN_NODES);
  float j00 = texture(ms_source_table, vec3(u, v, (b00 + zy) / depth)).r;
  float j01 = texture(ms_source_table, vec3(u, v, (b00 + sun_step + zy) / depth)).r;
  float j10 = texture(ms_source_table, vec3(u, v, (b00 + tau_step + zy) / depth)).r;
  float j11 = texture(ms_source_table, vec3(u, v, (b00 + tau_step + sun_step + zy) / depth)).r;
  return thin * max(mix(mix(j00, j01, fs), mix(j10, j11, fs), ft), 0.0);
}

// MsSourceTable::lookup of the diffuse table (model::ms_diffuse_incidence_table): the source
// of diffuse light entering through the top of a slab with optical depths tau_a above and
// tau_b below the point, towards zenith cosine mu_w. Light entering through the base:
// ms_diffuse_incidence_source(tau_b, tau_a, -mu_w). Linear in log2 tau over two texture blocks.
float ms_diffuse_incidence_source(float tau_a, float tau_b, float mu_w) {
  float tau = tau_a + tau_b;
  if (!(tau > 0.0)) return 0.0;
  int t0;
  float ft, thin;
  ms_tau_axis(tau, t0, ft, thin);
  float v = ms_mu_texcoord(mu_w);
  float zy = ms_depth_texel(tau_a, tau_b);
  const float depth = float(MS_DEPTH_BINS * MS_TAU_NODES);
  float b0 = float(MS_DEPTH_BINS * t0);
  float j0 = texture(ms_diffuse_incidence_table, vec3(0.5, v, (b0 + zy) / depth)).r;
  float j1 = texture(ms_diffuse_incidence_table, vec3(0.5, v, (b0 + float(MS_DEPTH_BINS) + zy) / depth)).r;
  return thin * max(mix(j0, j1, ft), 0.0);
}
