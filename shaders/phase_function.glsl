// Cloud phase function of Jendersie & d'Eon 2023 (HG + Draine blend fitted to Mie for
// water droplets); GPU twin of renderer/model/phase_function.cpp. Parameters per layer
// come from the droplet diameter on the CPU. sr^-1, normalised to 1 over the sphere.

// 1 + g^2 - 2 g mu written as (1 - g)^2 + 2 g (1 - mu): no cancellation in the forward
// peak, where g -> 1 and mu -> 1 (the naive form loses ~0.7 % near the peak at d = 50 in float).
float hg_denominator(float mu, float g) {
  float omg = 1.0 - g;
  return max(omg * omg + 2.0 * g * (1.0 - mu), 1e-12);
}

float hg_phase(float mu, float g) {
  return INV_4PI * (1.0 - g) * (1.0 + g) / pow(hg_denominator(mu, g), 1.5);
}

float draine_phase(float mu, float g, float alpha) {
  return hg_phase(mu, g) * (1.0 + alpha * mu * mu) / (1.0 + alpha * (1.0 + 2.0 * g * g) / 3.0);
}

#ifdef CLOUDSVC_MIE_PHASE
// The layers' tabulated Mie phase functions (renderer/model/mie_phase_table.h): row li of
// the texture, the angle's table position along it (0.02 deg steps to 5 deg, then 0.1 deg),
// linear between samples. sr^-1 per wavelength (rgb = 680 / 550 / 440 nm).
layout(binding = TEX_CLOUD_PHASE) uniform sampler2D cloud_phase_table;

vec3 tabulated_phase(int li, float cos_theta) {
  float theta = degrees(acos(clamp(cos_theta, -1.0, 1.0)));
  float x = theta <= PHASE_TABLE_FORWARD_END_DEG
                ? theta * PHASE_TABLE_FORWARD_PER_DEG
                : float(PHASE_TABLE_FORWARD_INTERVALS) + (theta - PHASE_TABLE_FORWARD_END_DEG) * PHASE_TABLE_REAR_PER_DEG;
  return texture(cloud_phase_table, vec2((x + 0.5) / float(PHASE_TABLE_SAMPLES), (float(li) + 0.5) / float(MAX_LAYERS))).rgb;
}
#endif

// p = (1 - w_D) HG(g_HG) + w_D Draine(g_D, alpha).
float cloud_phase(float mu, float g_hg, float g_d, float alpha, float w_d) {
  return (1.0 - w_d) * hg_phase(mu, g_hg) + w_d * draine_phase(mu, g_d, alpha);
}

// The sun's peak beam scattered towards the camera, per unit sun irradiance and unit
// scattering (peak_beam_phase, renderer/model/ms_source_table.h): the sun's light that has
// scattered only through the diffraction peak (the HG lobe, weight f = 1 - w_D), after a
// slant optical depth tau, in Poisson orders k with the peak broadened to HG(g_HG^(k+1)),
//   sum_k e^-tau (f tau)^k / k! [f HG(mu; g_HG^(k+1)) + (1 - f) D(mu)];
// k = 0 is single scattering. The Draine part sums to (1 - f) D(mu) e^-(1 - f) tau. At most
// PEAK_BEAM_ORDERS peak orders; the rest of the Poisson mass takes the next order's lobe.
float peak_beam_phase(float mu, float tau, float g_hg, float g_d, float alpha, float w_d) {
  float f = 1.0 - w_d;
  float beam = exp(-w_d * tau);
  float sum = w_d * draine_phase(mu, g_d, alpha) * beam;
  float term = exp(-tau), mass = 0.0, g = g_hg;
  for (int k = 0; k < PEAK_BEAM_ORDERS && mass < PEAK_BEAM_MASS_DONE * beam; ++k) {
    sum += f * term * hg_phase(mu, g);
    mass += term;
    term *= f * tau / float(k + 1);
    g *= g_hg;
  }
  return sum + f * max(beam - mass, 0.0) * hg_phase(mu, g);
}

// The optical depth towards the sun beyond which peak_beam_phase(mu, tau) stays below
// `negligible` for any tau (model::peak_beam_cutoff_tau, the same bound):
// [f max_k HG(mu; g_HG^(k+1)) + w_D D(mu)] e^(-w_D tau) <= negligible.
float peak_beam_cutoff_tau(float mu, float g_hg, float g_d, float alpha, float w_d, float negligible) {
  float lobe = 0.0, g = g_hg;
  for (int k = 0; k <= PEAK_BEAM_ORDERS; ++k) {
    lobe = max(lobe, hg_phase(mu, g));
    g *= g_hg;
  }
  float bound = (1.0 - w_d) * lobe + w_d * draine_phase(mu, g_d, alpha);
  return log(max(bound / negligible, 1.0)) / w_d;
}
