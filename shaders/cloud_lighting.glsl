// Light arriving at a point in a cloud layer: the sun through a light march (optical depth
// for the peak beam), diffuse light from Monte Carlo source tables (the sun's, and the
// sky's and the ground's diffuse light) with Monte Carlo slab transmittances to the ground,
// and the optical depth of a layer above a ground point (cloud shadows,
// ground_shadow_map.comp). Needs common.glsl, frame_uniforms.glsl, atmosphere_model.glsl,
// atmosphere_lookup.glsl, cloud_density.glsl.
#include "slab_transmittance.glsl"
#include "ms_source_lookup.glsl"
#include "column_quadrature.glsl"

// Length of the light march from altitude alt towards a sun of zenith cosine mu_s in layer
// li: to the layer's top, or its base where the path enters it from above, at most 4 km.
float light_march_length(int li, float alt, float mu_s) {
  float R = frame.shell_radius_m;
  vec2 exit_top = intersect_shell(R, alt, frame.layers[li].top_m, mu_s);
  vec2 hit_base = intersect_shell(R, alt, frame.layers[li].base_m, mu_s);
  float len = exit_top.y > 0.0 ? exit_top.y : 0.0;
  if (hit_base.x > 0.0) len = min(len, hit_base.x);
  return min(len, LIGHT_MARCH_REACH_M);
}

// Optical depth from point p (altitude alt) towards the sun inside layer li, in n steps
// spaced quadratically (fine near the sample, coarse far away), with the weather map
// value w of the sample (cloud_extinction_in: the map varies over ~40 km, the march
// spans at most 4 km; one map read instead of n). Stops once tau exceeds tau_cut (the
// sun's beam is spent there; 1e30: never); marched: the length marched (m).
float light_optical_depth(int li, vec3 p, float alt, vec3 sun, float mu_s, int n, vec4 w, float tau_cut,
                          out float marched) {
  marched = 0.0;
  if (frame.layers[li].coverage <= 0.0) return 0.0;  // coverage 0 (renderer/coverage_cull.h): no cloud
  float R = frame.shell_radius_m;
  float len = light_march_length(li, alt, mu_s);
  float tau = 0.0, s_prev = 0.0;
  for (int j = 0; j < n; ++j) {
    float f = float(j + 1) / float(n);
    float s = len * f * f;
    vec3 x = p + sun * (0.5 * (s + s_prev));
    float ax = altitude_of(x, R, frame.camera_altitude_m);
    float coverage;
    tau += cloud_extinction_in(li, x, ax, DETAIL_NONE, w, coverage) * (s - s_prev);
    s_prev = s;
    if (tau > tau_cut) break;  // the beam is spent: e^-tau < e^-tau_cut whatever lies beyond
  }
  marched = s_prev;
  return tau;
}

// The slab the sun's diffuse source is read from, tilted towards the sun (side illumination
// of 3-D clouds; reference::tilted_sun_slab has the model and its sources): mu the cosine
// between its normal and the sun, its depths above (to the sunlit face) and below the point,
// and the scattered light's cosine w_n and azimuth cosine about its normal.
struct SunSlab {
  float mu, above, below, w_n, cos_phi;
};

// The fraction of the column above a point (to_top_m below the layer's top) that a light
// march of marched_m towards a sun of zenith cosine mu_s spans vertically, at most 1.
float sun_window(float marched_m, float mu_s, float to_top_m) {
  return to_top_m > 0.0 ? clamp(marched_m * max(mu_s, 0.0) / to_top_m, 0.0, 1.0) : 1.0;
}

// The horizontal slab of the column: column = (below, above) optical depths of the point's
// column; up, sun, w (the scattered light's direction) unit vectors.
SunSlab vertical_sun_slab(vec2 column, vec3 up, vec3 sun, vec3 w) {
  float mu_s = dot(up, sun);
  float w_up = dot(w, up);
  vec3 sun_h = sun - mu_s * up, w_h = w - w_up * up;
  float hh = dot(sun_h, sun_h) * dot(w_h, w_h);
  return SunSlab(mu_s, column.y, column.x, w_up, hh > 1e-12 ? dot(sun_h, w_h) * inversesqrt(hh) : 1.0);
}

// ... tilted towards the sun: tau_sun the light march's depth over the window of the sun's
// path (sun_window).
SunSlab tilted_sun_slab(vec2 column, float tau_sun, float window, vec3 up, vec3 sun, vec3 w) {
  float mu_s = dot(up, sun);
  float s_h = sqrt(max(1.0 - mu_s * mu_s, 0.0));
  if (!(mu_s > 0.0) || s_h < 1e-6) return vertical_sun_slab(column, up, sun, w);  // no sun, or overhead
  float f = clamp(window, 0.0, 1.0);
  float mu = clamp(f * column.y / max(tau_sun, 1e-30), mu_s, 1.0);
  float above = mu * tau_sun + (1.0 - f) * column.y;
  float below = column.x + max(column.y - above, 0.0);
  // the normal: in the plane of up and sun, at cosine mu from the sun (mu = mu_s: up)
  vec3 n = mu * sun + sqrt(max(1.0 - mu * mu, 0.0)) * ((up - mu_s * sun) / s_h);
  float w_n = dot(w, n);
  vec3 sun_t = sun - mu * n, w_t = w - w_n * n;
  float tt = dot(sun_t, sun_t) * dot(w_t, w_t);
  return SunSlab(mu, above, below, w_n, tt > 1e-12 ? dot(sun_t, w_t) * inversesqrt(tt) : 1.0);
}

// Optical depth of layer li from a ground point p towards the sun (cloud shadows), in
// n equal steps through the layer (base shape only).
float layer_shadow_optical_depth(int li, vec3 p, float ground_alt, vec3 sun, float mu_s, int n) {
  if (frame.layers[li].coverage <= 0.0) return 0.0;  // coverage 0 (renderer/coverage_cull.h): no cloud
  float R = frame.shell_radius_m;
  float t_base = intersect_shell(R, ground_alt, frame.layers[li].base_m, mu_s).y;
  float t_top = intersect_shell(R, ground_alt, frame.layers[li].top_m, mu_s).y;
  if (t_top <= 0.0) return 0.0;
  t_base = max(t_base, 0.0);
  float dt = (t_top - t_base) / float(n);
  float tau = 0.0;
  for (int j = 0; j < n; ++j) {
    vec3 x = p + sun * (t_base + (float(j) + 0.5) * dt);
    tau += cloud_extinction(li, x, altitude_of(x, R, frame.camera_altitude_m), DETAIL_NONE) * dt;
  }
  return tau;
}

// Transmittance of layer L's full nominal optical depth for the sun's beam at zenith cosine
// mu0: CloudLayerGpu::ground_transmittance, linear in mu0 between the table's nodes (as
// slab_beam_transmittance interpolates).
float layer_beam_transmittance(CloudLayerGpu L, float mu0) {
  float fm;
  int j = slab_flux_mu_index(mu0, fm);
  return mix(L.ground_transmittance[j / 4][j % 4], L.ground_transmittance[(j + 1) / 4][(j + 1) % 4], fm);
}

// Diffuse in-scattered radiance (per unit scattering) at altitude alt inside layer L: the light
// scattered more than once, with the optical depths tau_a above and tau_b below the point
// through its own column (the column volume, column_volume.glsl, or a homogeneous layer's) and
// the map's local coverage c.
// * The sun's: the Monte Carlo source table (ms_source_over_mu) at the depths of the sun's
//   slab (vertical_sun_slab, or tilted_sun_slab with RenderQuality::sun_slab_tilt, which is
//   the horizontal one in a horizontally homogeneous layer) times the solar flux through its
//   face F_sun = E_sun T_atm mu', optical depths scaled to the table's droplets by
//   (1 - g) / (1 - g_table) (similarity; L.ms_similarity).
//   With the peak beam of the sun term (peak_beam_phase) it makes the slab radiances of
//   Monte Carlo (docs/ACCURACY.md).
// * The sky's and the ground's: the Monte Carlo source of diffuse light
//   (ms_diffuse_incidence_source) entering through the layer's top (the sky's irradiance E_sky at the point's altitude)
//   and through its base (the table turned upside down), with E_up = a E_g the light a
//   ground of albedo a sends up: its irradiance E_g under the layer, as independent
//   columns (a fraction 1 - c of the ground in the clear, c under the layer's full optical
//   depth tau_c: sun through 1 - c + c T_beam(tau_c), sky through 1 - c + c T(tau_c), both
//   at ground level; slab_transmittance.glsl) with the round trips between ground and cloud
//   (ground_cloud_gain(c a, tau_c)):
//     J = E_sky J_dif(tau_a, tau_b, w_up) + E_up J_dif(tau_b, tau_a, -w_up).
// w_up: the scattered light's zenith cosine (the sky's and the ground's sources).
// above: what the layers above the point let through (layers_above_light, layers_above.glsl:
// x the sun's direct beam, y the sky's light, z the sun's light they scatter, entering the
// top as diffuse light), applied to the sun's source, the light entering the top and the
// ground's irradiance alike; (1, 1, 0) without layers above.
// ground_sun and ground_sky (cloud_free_ground_irradiance below) are the irradiance the
// ground under the point would receive without clouds, albedo its albedo (ground_albedo_at);
// the march holds all three over 10 km of its ray (the sun's zenith angle at the ground below
// a sample moves by 1.6e-4 rad per km).
vec3 diffuse_inscatter(CloudLayerGpu L, float alt, float tau_above, float tau_below, SunSlab sun_slab, float mu_s,
                       vec3 T_atm, float coverage, vec3 E_sun, vec3 ground_sun, vec3 ground_sky, vec3 albedo, float w_up,
                       vec3 above) {
  // the optical depths above and below the point, scaled to the tables' droplets
  float sa = L.ms_similarity * tau_above;
  float sb = L.ms_similarity * tau_below;
  float mu_pos = max(mu_s, 0.0);
  vec3 J_sun = vec3(0.0);
  if (mu_pos > 0.0) {
    float phi_deg = degrees(acos(clamp(sun_slab.cos_phi, -1.0, 1.0)));
    J_sun = E_sun * T_atm *
            (above.x * sun_slab.mu *
             ms_source_over_mu(L.ms_similarity * sun_slab.above, L.ms_similarity * sun_slab.below, sun_slab.mu,
                               sun_slab.w_n, phi_deg));
  }
  // diffuse light onto the layer's top: the sky's, and the sun's the layers above scatter
  vec3 E_sky = E_sun * (sky_irradiance(alt, mu_s) * above.y + T_atm * (mu_pos * above.z));
  float mu0 = max(mu_pos, 0.05);
  // the ground under the layer: a fraction 1 - c in the clear, c under cloud of the layer's
  // full optical depth (independent columns), with the round trips to the cloud's base
  float c = clamp(coverage, 0.0, 1.0);
  // (the layer's full optical depth tau_c's transmittances: L.ground_transmittance, per frame)
  float T_sky_cloud = L.ground_transmittance[2].w;
  float T_sun_ground = 1.0 - c + c * (mu_pos > 0.0 ? layer_beam_transmittance(L, mu0) : 0.0);
  float T_sky_ground = 1.0 - c + c * T_sky_cloud;
  vec3 E_up = albedo * ground_cloud_gain_for_transmittance(albedo * c, T_sky_cloud) *
              (ground_sun * (above.x * T_sun_ground + above.z * T_sky_ground) + ground_sky * (above.y * T_sky_ground));
  return J_sun + E_sky * ms_diffuse_incidence_source(sa, sb, w_up) + E_up * ms_diffuse_incidence_source(sb, sa, -w_up);
}

// Irradiance of the ground at altitude ground_alt without clouds (W m^-2 nm^-1), for a sun
// at zenith cosine mu_s: the sun's part through the atmosphere and the sky's. The ground's
// input to diffuse_inscatter.
void cloud_free_ground_irradiance(float ground_alt, float mu_s, vec3 E_sun, out vec3 from_sun, out vec3 from_sky) {
  from_sun = E_sun * transmittance_to_space(ground_alt, mu_s) * max(mu_s, 0.0);
  from_sky = E_sun * sky_irradiance(ground_alt, mu_s);
}
