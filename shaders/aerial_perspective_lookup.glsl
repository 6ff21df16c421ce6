// Lookup into the aerial-perspective volume (aerial_perspective.comp, Hillaire 2020 §5.4):
// froxels of the current camera, 32 slices to frame.ap_max_distance_m metres.
layout(binding = TEX_AP_INSCATTER) uniform sampler3D ap_inscatter;      // rgb in-scattered radiance for unit sun irradiance (sr^-1)
layout(binding = TEX_AP_TRANSMITTANCE) uniform sampler3D ap_transmittance;  // rgb transmittance from the camera

// Aerial perspective lookup: in-scatter (unit sun) and transmittance to distance t along
// the view ray dir (unit, local frame; inside the volume's frustum, which holds the
// camera's: AtmosphereLuts::plan_view_dependent).
// Slices sit at d_max (k / (n - 1))^2. Between the two slices around t the air is taken as
// uniform, as the march that filled them does per step: T(t) = T0 e^{-sigma x} with
// sigma = ln(T0 / T1) / (d1 - d0) and x = t - d0, and L(t) = L0 + (L1 - L0) (1 - e^{-sigma x})
// / (1 - e^{-sigma (d1 - d0)}), per channel; linear in distance where the slab is thin.
// Exact for uniform air: in haze (1 km visibility: extinction 3e-3 / m) a slab a few km deep
// holds several optical depths, and linear interpolation erred by 10 % and more.
void aerial_perspective(vec3 dir, float t, out vec3 inscatter, out vec3 transmittance) {
  vec3 n = vec3(textureSize(ap_inscatter, 0));
  float k = sqrt(saturate(t / frame.ap_max_distance_m)) * (n.z - 1.0);
  float k0 = min(floor(k), n.z - 2.0);
  float d0 = frame.ap_max_distance_m * (k0 / (n.z - 1.0)) * (k0 / (n.z - 1.0));
  float d1 = frame.ap_max_distance_m * ((k0 + 1.0) / (n.z - 1.0)) * ((k0 + 1.0) / (n.z - 1.0));
  float x = clamp(t - d0, 0.0, d1 - d0);
  float z = max(dot(dir, frame.ap_forward), 1e-6);
  vec2 ndc = vec2(dot(dir, frame.ap_right) / (z * frame.ap_tan_half_width), dot(dir, frame.ap_up) / (z * frame.ap_tan_half_height));
  vec2 uv = ((ndc * 0.5 + 0.5) * (n.xy - 1.0) + 0.5) / n.xy;
  float w0 = (k0 + 0.5) / n.z, w1 = (k0 + 1.5) / n.z;
  vec3 L0 = textureLod(ap_inscatter, vec3(uv, w0), 0.0).rgb, L1 = textureLod(ap_inscatter, vec3(uv, w1), 0.0).rgb;
  vec3 T0 = textureLod(ap_transmittance, vec3(uv, w0), 0.0).rgb, T1 = textureLod(ap_transmittance, vec3(uv, w1), 0.0).rgb;
  vec3 tau = max(log(max(T0, vec3(1e-30)) / max(T1, vec3(1e-30))), vec3(0.0));  // the slab's optical depth
  vec3 f_lin = vec3(x / max(d1 - d0, 1e-3));
  vec3 f_exp = (vec3(1.0) - exp(-tau * f_lin)) / max(vec3(1.0) - exp(-tau), vec3(1e-30));
  vec3 f = mix(f_lin, f_exp, step(vec3(1e-3), tau));
  inscatter = L0 + (L1 - L0) * f;
  transmittance = T0 * exp(-tau * f_lin);
}
