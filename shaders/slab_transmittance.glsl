// Transmittance of a conservative scattering slab of clouds (two-stream, delta-scaled):
// the diffuse light under a layer and the sun's beam through it (cloud_lighting.glsl,
// and the composite's ground under cloud shadows). Needs common.glsl.
// delta-scaling (Joseph, Wiscombe & Weinman 1976): the forward peak, a fraction g^2 of the
// scattering, is counted as unscattered light in the two-stream fluxes
const float DELTA_F = TWO_STREAM_MEAN_COSINE * TWO_STREAM_MEAN_COSINE;

// Diffuse transmittance of a conservative slab of optical depth tau lit by diffuse light
// (two-stream, Bohren 1987 "Multiple scattering of light and some of its observable
// consequences"); delta-scaling leaves (1 - g) tau unchanged.
float slab_diffuse_transmittance(float tau) { return 1.0 / (1.0 + 0.75 * (1.0 - TWO_STREAM_MEAN_COSINE) * tau); }

// Total (direct + diffuse) transmittance of a conservative slab of optical depth tau for
// a collimated beam at zenith cosine mu0 > 0: the delta-Eddington solution
//   T = [(1/2 + 3/4 mu0) + (1/2 - 3/4 mu0) e^{-tau'/mu0}] / (1 + 3/4 (1 - g) tau),
// tau' = (1 - g^2) tau; the direct part is e^{-tau'/mu0}. Equal to the diffuse form at
// mu0 = 2/3, and 1 at tau = 0.
float slab_beam_transmittance(float tau, float mu0) {
  float direct = exp(-(1.0 - DELTA_F) * tau / mu0);
  return ((0.5 + 0.75 * mu0) + (0.5 - 0.75 * mu0) * direct) / (1.0 + 0.75 * (1.0 - TWO_STREAM_MEAN_COSINE) * tau);
}

// Light bouncing between a Lambertian ground of albedo a and a conservative slab of
// optical depth tau above it: the irradiance reaching the ground gains the geometric series
// 1 / (1 - a R) of ground-cloud round trips, R = 1 - T(tau) the slab's diffuse reflectance
// from below (the adding method, e.g. Liou 2002 §6.2; Bouthors et al. 2008 §5 for clouds).
vec3 ground_cloud_gain(vec3 albedo, float tau) {
  return 1.0 / (1.0 - albedo * (1.0 - slab_diffuse_transmittance(tau)));
}
