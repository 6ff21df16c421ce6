// Light reaching a cloud layer through the layers above it (multilayer skies: a cumulus or
// stratocumulus layer under an altostratus, cirrus or anvil deck). The layers above shade
// the sun's beam, pass part of it and of the sky's light on as diffuse light, and bounce the
// light the lower layer reflects back down to it. Twin of
// reference::layers_above_optical_depth / layers_above_light
// (renderer/reference/cloud_lighting.h). Needs common.glsl, frame_uniforms.glsl and the
// files cloud_lighting.glsl needs.
#include "slab_transmittance.glsl"
#include "ground_shadow_map.glsl"
#include "cloud_lighting.glsl"

// Is layer lj drawn above layer li (its base at or above li's top, its coverage > 0)?
bool layer_is_above(int lj, int li) {
  return lj != li && frame.layers[lj].base_m >= frame.layers[li].top_m && frame.layers[lj].coverage > 0.0;
}

// Optical depth towards the sun (along the slant path) of the layers above layer li, those
// whose base is at or above li's top, from local point p at altitude alt, sun zenith cosine
// mu_s there. From the ground shadow map where there is one: each upper layer's depth at the
// ground point whose sun ray passes through p (the same ray above p; where that ray misses
// the ground, a sun below ~3 degrees seen from a high layer, the map's value under its point
// nearest the ground). Without the map (the naive preset, per-pixel ground shadows) a march
// of each upper layer from p (layer_shadow_optical_depth) in the map's ground_shadow_steps,
// at most LAYERS_ABOVE_MAX_STEPS.
// llvmpipe runs at most 65535 loop iterations per invocation, all loops together: a fine
// march (1024 primary steps, 32 light steps) with the 128 per-pixel ground steps it uses
// for ground shadows at every sample would pass it.
const int LAYERS_ABOVE_MAX_STEPS = 16;
float layers_above_optical_depth(int li, vec3 p, float alt, vec3 sun, float mu_s) {
  if (mu_s <= 0.0) return 0.0;
  float tau = 0.0;
  bool map = shadow.map_valid != 0;
  vec3 g = p;
  if (map) {
    float R = frame.shell_radius_m;
    vec2 hit = intersect_shell(R, alt, frame.ground_altitude_m, -mu_s);
    // distance along -sun to the ground, or to the ray's point nearest the ground
    float t = hit.x > 0.0 ? hit.x : (R + alt) * mu_s;
    g = p - sun * t;
  }
  for (int lj = 0; lj < frame.layer_count; ++lj) {
    if (!layer_is_above(lj, li)) continue;
    tau += map ? shadow_map_optical_depth(lj, g) : layer_shadow_optical_depth(lj, p, alt, sun, mu_s, min(frame.ground_shadow_steps, LAYERS_ABOVE_MAX_STEPS));
  }
  return tau;
}

// What the layers above (slant optical depth tau towards the sun) let through to a layer
// whose diffuse reflectance from above is r_low, as factors of the light at the top of the
// clouds: x the sun's direct beam, e^-tau; y the sky's diffuse light, T_dif(tau_v) g; z the
// sun's light arriving diffuse, T_beam(tau_v, mu0) g - e^-tau (per unit horizontal solar
// flux). tau_v = tau mu_s is their vertical optical depth (a plane-parallel slab, as
// composite.comp's ground), T_dif and T_beam the Monte Carlo slab transmittances
// (slab_transmittance.glsl), and g = 1 / (1 - r_low (1 - T_dif(tau_v))) the round trips
// between the two layers (the adding method, as ground_cloud_gain between ground and cloud;
// Liou 2002 §6.2). No layers above: (1, 1, 0).
vec3 layers_above_light(float tau, float mu_s, float r_low) {
  if (!(tau > 0.0)) return vec3(1.0, 1.0, 0.0);
  float tau_v = tau * max(mu_s, 0.0);
  float T_dif = slab_diffuse_transmittance(tau_v);
  float gain = 1.0 / (1.0 - clamp(r_low, 0.0, 1.0) * (1.0 - T_dif));
  float direct = exp(-tau);
  float sun_diffuse = mu_s > 0.0 ? max(slab_beam_transmittance(tau_v, max(mu_s, 0.05)) * gain - direct, 0.0) : 0.0;
  return vec3(direct, T_dif * gain, sun_diffuse);
}

// Diffuse reflectance from above of layer L where the map's coverage is c: the cloudy
// fraction reflects 1 - T_dif of its full optical depth (CloudLayerGpu::ground_transmittance),
// the clear fraction nothing.
float layer_diffuse_reflectance(CloudLayerGpu L, float c) {
  return clamp(c, 0.0, 1.0) * (1.0 - L.ground_transmittance[2].w);
}
