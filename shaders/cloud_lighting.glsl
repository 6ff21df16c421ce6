// Light arriving at a point in a cloud layer: the sun through a light march (optical
// depth for the Wrenninge octaves), diffuse light from two-stream slab theory, and the
// optical depth of a layer above a ground point (cloud shadows, ground_shadow_map.comp). Needs common.glsl,
// frame_uniforms.glsl, atmosphere_model.glsl, atmosphere_lookup.glsl, cloud_density.glsl.

const float LIGHT_MAX_DIST = 4000.0;  // m, longest light march
const float MEAN_COSINE = 0.86;       // droplet phase mean cosine used for diffuse transfer

// Diffuse transmittance of a conservative slab of optical depth tau (two-stream,
// Bohren 1987 "Multiple scattering of light and some of its observable consequences").
float slab_diffuse_transmittance(float tau) { return 1.0 / (1.0 + 0.75 * (1.0 - MEAN_COSINE) * tau); }

// Optical depth from point p (altitude alt) towards the sun inside layer li, in n steps
// spaced quadratically (fine near the sample, coarse far away).
float light_optical_depth(int li, vec3 p, float alt, vec3 sun, float mu_s, int n) {
  float R = U.planet.x;
  vec2 exit_top = intersect_shell(R, alt, U.layers[li].altitude.y, mu_s);
  vec2 hit_base = intersect_shell(R, alt, U.layers[li].altitude.x, mu_s);
  float len = exit_top.y > 0.0 ? exit_top.y : 0.0;
  if (hit_base.x > 0.0) len = min(len, hit_base.x);
  len = min(len, LIGHT_MAX_DIST);
  float tau = 0.0, s_prev = 0.0;
  for (int j = 0; j < n; ++j) {
    float f = float(j + 1) / float(n);
    float s = len * f * f;
    vec3 x = p + sun * (0.5 * (s + s_prev));
    float ax = altitude_of(x, R, U.planet.y);
    tau += cloud_extinction(li, x, ax, DETAIL_NONE) * (s - s_prev);
    s_prev = s;
  }
  return tau;
}

// Optical depth of layer li from a ground point p towards the sun (cloud shadows), in
// n equal steps through the layer (base shape only).
float layer_shadow_optical_depth(int li, vec3 p, float ground_alt, vec3 sun, float mu_s, int n) {
  float R = U.planet.x;
  float t_base = intersect_shell(R, ground_alt, U.layers[li].altitude.x, mu_s).y;
  float t_top = intersect_shell(R, ground_alt, U.layers[li].altitude.y, mu_s).y;
  if (t_top <= 0.0) return 0.0;
  t_base = max(t_base, 0.0);
  float dt = (t_top - t_base) / float(n);
  float tau = 0.0;
  for (int j = 0; j < n; ++j) {
    vec3 x = p + sun * (t_base + (float(j) + 0.5) * dt);
    tau += cloud_extinction(li, x, altitude_of(x, R, U.planet.y), DETAIL_NONE) * dt;
  }
  return tau;
}

// Diffuse in-scattered radiance (per unit scattering) at altitude alt inside layer L, from
// two-stream slab theory for conservative scattering (Bohren 1987): with vertical optical
// depths tau_a above and tau_b below the point, estimated from the layer's nominal
// extinction and the local coverage,
//   T(tau) = 1 / (1 + 3/4 (1 - g) tau),   R(tau) = 1 - T(tau),
//   F_down = F_sun (T(tau_a) - e^{-tau_a / mu_s}) + E_sky T(tau_a)      (diffuse only)
//   F_up   = (F_sun + E_sky) T(tau_a) R(tau_b) + E_ground T(tau_b)
// Each flux is taken as isotropic over its hemisphere (radiance F / pi), so the
// in-scatter averaged over directions is (F_down + F_up) / (2 pi). This supplies the
// light that the few octaves of the sun march cannot carry deep into a cloud or back
// out of its top.
vec3 diffuse_inscatter(CloudLayerGpu L, float alt, float mu_s, vec3 T_atm, float coverage, vec3 E_sun,
                       float ground_alt) {
  float sigma_nominal = L.optics.x * L.altitude.w * coverage;
  float tau_a = sigma_nominal * max(L.altitude.y - alt, 0.0);
  float tau_b = sigma_nominal * max(alt - L.altitude.x, 0.0);
  float Ta = slab_diffuse_transmittance(tau_a), Tb = slab_diffuse_transmittance(tau_b);
  float mu_pos = max(mu_s, 0.0);
  vec3 F_sun = E_sun * T_atm * mu_pos;
  vec3 E_sky = E_sun * sky_irradiance(alt, mu_s);
  vec3 E_ground = U.ground_albedo.rgb * E_sun *
                  (transmittance_to_space(ground_alt, mu_s) * mu_pos + sky_irradiance(ground_alt, mu_s));
  float direct_a = mu_pos > 0.0 ? exp(-tau_a / max(mu_pos, 0.05)) : 0.0;
  vec3 F_down = F_sun * max(Ta - direct_a, 0.0) + E_sky * Ta;
  vec3 F_up = (F_sun + E_sky) * Ta * (1.0 - Tb) + E_ground * Tb;
  return (F_down + F_up) / (2.0 * PI);
}
