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

// p = (1 - w_D) HG(g_HG) + w_D Draine(g_D, alpha). `eccentricity` scales both g for
// multiple-scattering octaves (Wrenninge et al. 2013: g c^i).
float cloud_phase(float mu, float g_hg, float g_d, float alpha, float w_d, float eccentricity) {
  return (1.0 - w_d) * hg_phase(mu, g_hg * eccentricity) +
         w_d * draine_phase(mu, g_d * eccentricity, alpha);
}
