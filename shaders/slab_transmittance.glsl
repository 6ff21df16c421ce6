// Transmittance of a conservative scattering slab of clouds: the diffuse light under a
// layer and the sun's beam through it (cloud_lighting.glsl, and the composite's ground
// under cloud shadows). The Monte Carlo table of renderer/model/slab_flux_table.h, whose
// arrays and grid the preamble holds (renderer/gpu_interface.cpp); the same lookups as
// model::slab_beam_transmittance / slab_diffuse_transmittance. Needs common.glsl.

// f(tau) from values v0 (tau node 0), vi, vi1 (nodes i, i + 1 around tau) and vn (the
// last node), as the table interpolates: linear in log2 tau between nodes, 1 - (1 - v0)
// tau / tau_min below the first, the diffusion limit vn (tau_max + b) / (tau + b) above.
int slab_flux_tau_index(float tau, out float frac) {
  float x = log2(max(tau, 1e-30) / SLAB_FLUX_TAU_MIN);
  int i = clamp(int(floor(x)), 0, SLAB_FLUX_TAU_NODES - 2);
  frac = x - float(i);
  return i;
}

float slab_flux_in_tau(float tau, int i, float frac, float v0, float vi, float vi1, float vn) {
  if (!(tau > 0.0)) return 1.0;
  float tau_max = SLAB_FLUX_TAU_MIN * exp2(float(SLAB_FLUX_TAU_NODES - 1));
  if (tau <= SLAB_FLUX_TAU_MIN) return 1.0 - (1.0 - v0) * tau / SLAB_FLUX_TAU_MIN;
  if (tau >= tau_max) return vn * (tau_max + SLAB_FLUX_DIFFUSION_OFFSET) / (tau + SLAB_FLUX_DIFFUSION_OFFSET);
  return mix(vi, vi1, frac);
}

// Transmittance of diffuse light through a slab of optical depth tau (1 at tau = 0).
float slab_diffuse_transmittance(float tau) {
  float frac;
  int i = slab_flux_tau_index(tau, frac);
  return slab_flux_in_tau(tau, i, frac, SLAB_FLUX_DIFFUSE[0], SLAB_FLUX_DIFFUSE[i], SLAB_FLUX_DIFFUSE[i + 1],
                          SLAB_FLUX_DIFFUSE[SLAB_FLUX_TAU_NODES - 1]);
}

// The table's sun-cosine node j at or below mu0 (clamped to the grid) and the weight fm of
// node j + 1: linear interpolation in mu0.
int slab_flux_mu_index(float mu0, out float fm) {
  float m = clamp((mu0 - SLAB_FLUX_MU_MIN) / SLAB_FLUX_MU_STEP, 0.0, float(SLAB_FLUX_MU_NODES - 1));
  int j = min(int(m), SLAB_FLUX_MU_NODES - 2);
  fm = m - float(j);
  return j;
}

// Total (direct + diffuse) transmittance of a collimated beam at zenith cosine mu0 > 0.
float slab_beam_transmittance(float tau, float mu0) {
  float fm;
  int j = slab_flux_mu_index(mu0, fm);
  float frac;
  int i = slab_flux_tau_index(tau, frac);
  int n = SLAB_FLUX_MU_NODES, last = (SLAB_FLUX_TAU_NODES - 1) * n;
  float v0 = mix(SLAB_FLUX_BEAM[j], SLAB_FLUX_BEAM[j + 1], fm);
  float vi = mix(SLAB_FLUX_BEAM[i * n + j], SLAB_FLUX_BEAM[i * n + j + 1], fm);
  float vi1 = mix(SLAB_FLUX_BEAM[(i + 1) * n + j], SLAB_FLUX_BEAM[(i + 1) * n + j + 1], fm);
  float vn = mix(SLAB_FLUX_BEAM[last + j], SLAB_FLUX_BEAM[last + j + 1], fm);
  return slab_flux_in_tau(tau, i, frac, v0, vi, vi1, vn);
}

// Light bouncing between a Lambertian ground of albedo a and a conservative slab of
// optical depth tau above it: the irradiance reaching the ground gains the geometric series
// 1 / (1 - a R) of ground-cloud round trips, R = 1 - T(tau) the slab's diffuse reflectance
// from below (the adding method, e.g. Liou 2002 §6.2; Bouthors et al. 2008 §5 for clouds).
// With the slab's diffuse transmittance T given:
vec3 ground_cloud_gain_for_transmittance(vec3 albedo, float T) { return 1.0 / (1.0 - albedo * (1.0 - T)); }
vec3 ground_cloud_gain(vec3 albedo, float tau) {
  return ground_cloud_gain_for_transmittance(albedo, slab_diffuse_transmittance(tau));
}
