// Lookup into the aerial-perspective volume (aerial_perspective.comp, Hillaire 2020 §5.4):
// froxels of the current camera, 32 slices to frame.ap_max_distance_m metres.
layout(binding = TEX_AP_INSCATTER) uniform sampler3D ap_inscatter;      // rgb in-scattered radiance for unit sun irradiance (sr^-1)
layout(binding = TEX_AP_TRANSMITTANCE) uniform sampler3D ap_transmittance;  // rgb transmittance from the camera

// Aerial perspective lookup: in-scatter (unit sun) and transmittance to distance t along
// the view ray dir (unit, local frame; inside the volume's frustum, which holds the
// camera's: AtmosphereLuts::plan_view_dependent).
// Slices sit at d_max (k / (n - 1))^2, so the slice coordinate is interpolated linearly in
// distance between the two neighbouring slices (linear in k would overestimate the
// in-scatter by up to 8 % near the camera).
void aerial_perspective(vec3 dir, float t, out vec3 inscatter, out vec3 transmittance) {
  vec3 n = vec3(textureSize(ap_inscatter, 0));
  float k = sqrt(saturate(t / frame.ap_max_distance_m)) * (n.z - 1.0);
  float k0 = min(floor(k), n.z - 2.0);
  float d0 = frame.ap_max_distance_m * (k0 / (n.z - 1.0)) * (k0 / (n.z - 1.0));
  float d1 = frame.ap_max_distance_m * ((k0 + 1.0) / (n.z - 1.0)) * ((k0 + 1.0) / (n.z - 1.0));
  k = k0 + saturate((t - d0) / max(d1 - d0, 1e-3));
  float z = max(dot(dir, frame.ap_forward), 1e-6);
  vec2 ndc = vec2(dot(dir, frame.ap_right) / (z * frame.ap_tan_half_width), dot(dir, frame.ap_up) / (z * frame.ap_tan_half_height));
  vec3 tc = vec3((ndc * 0.5 + 0.5) * (n.xy - 1.0) + 0.5, k + 0.5) / n;
  inscatter = textureLod(ap_inscatter, tc, 0.0).rgb;
  transmittance = textureLod(ap_transmittance, tc, 0.0).rgb;
}
