#version 450 core
// One frame: clouds marched through the layer intervals of each pixel's ray, over the sky
// (sky-view LUT + sun disk) or the ground (lit by sun and sky, shadowed by the same cloud
// density field), with aerial perspective. Output: linear spectral radiance at 680/550/
// 440 nm (W m^-2 sr^-1 nm^-1) in rgb, cloud opacity (1 - cloud transmittance) in a.
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "sky_view_mapping.glsl"
#include "phase_function.glsl"
#include "cloud_density.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D out_image;
layout(binding = 6) uniform sampler2D sky_view_lut;
layout(binding = 7) uniform sampler3D ap_inscatter;
layout(binding = 8) uniform sampler3D ap_transmittance;
layout(std430, binding = 0) buffer FrameCounters {
  uint density_evals;
  uint nonfinite_pixels;
  uint cloud_pixels;
} counters;

const int MAX_INTERVALS = 8;
const float CLOUD_T_EPS = 1e-3;   // early exit below this cloud transmittance
const float LIGHT_MAX_DIST = 4000.0;  // m, longest light march
const float MEAN_COSINE = 0.86;   // droplet phase mean cosine used for diffuse transfer

// Diffuse transmittance of a conservative slab of optical depth tau (two-stream,
// Bohren 1987 "Multiple scattering of light and some of its observable consequences").
float slab_diffuse_transmittance(float tau) { return 1.0 / (1.0 + 0.75 * (1.0 - MEAN_COSINE) * tau); }

struct Interval { float t0; float t1; int layer; };

// March coordinate u(t) = ln(1 + t / t_ref) (or t itself when t_ref = 0) and its inverse.
float march_coordinate(float t, float t_ref) { return t_ref > 0.0 ? log(1.0 + t / t_ref) : t; }
float march_distance(float u, float t_ref) { return t_ref > 0.0 ? t_ref * (exp(u) - 1.0) : u; }

// The part of the ray inside layer li, as up to two intervals [entry, exit] clipped to
// [0, t_limit]: inside the top sphere and outside the base sphere.
int layer_intervals(int li, float mu, float t_limit, out Interval a, out Interval b) {
  float R = U.planet.x, h = U.planet.y;
  vec2 top = intersect_shell(R, h, U.layers[li].altitude.y, mu);
  vec2 base = intersect_shell(R, h, U.layers[li].altitude.x, mu);
  int n = 0;
  if (top.y < 0.0) return 0;
  float A0 = max(top.x, 0.0), A1 = min(top.y, t_limit);
  if (A0 >= A1) return 0;
  if (base.y < 0.0 || base.y <= A0 || max(base.x, 0.0) >= A1) {
    a = Interval(A0, A1, li);
    return 1;
  }
  float B0 = max(base.x, 0.0), B1 = base.y;
  if (B0 > A0) { a = Interval(A0, B0, li); n = 1; }
  if (B1 < A1) {
    if (n == 0) a = Interval(B1, A1, li); else b = Interval(B1, A1, li);
    n += 1;
  }
  return n;
}

// Optical depth from point p (altitude alt) towards the sun inside layer li.
float light_optical_depth(int li, vec3 p, float alt, vec3 sun, float mu_s) {
  float R = U.planet.x;
  vec2 exit_top = intersect_shell(R, alt, U.layers[li].altitude.y, mu_s);
  vec2 hit_base = intersect_shell(R, alt, U.layers[li].altitude.x, mu_s);
  float len = exit_top.y > 0.0 ? exit_top.y : 0.0;
  if (hit_base.x > 0.0) len = min(len, hit_base.x);
  len = min(len, LIGHT_MAX_DIST);
  int n = int(U.quality.y);
  float tau = 0.0, s_prev = 0.0;
  for (int j = 0; j < n; ++j) {
    float f = float(j + 1) / float(n);
    float s = len * f * f;  // quadratic spacing: fine near the sample, coarse far away
    vec3 x = p + sun * (0.5 * (s + s_prev));
    float ax = altitude_of(x, R, U.planet.y);
    tau += cloud_extinction(li, x, ax, false) * (s - s_prev);
    s_prev = s;
  }
  return tau;
}

// Optical depth of all layers from a ground point towards the sun (cloud shadows).
float ground_shadow_optical_depth(vec3 p, float ground_alt, vec3 sun, float mu_s) {
  float R = U.planet.x;
  int n = int(U.quality.w);
  float tau = 0.0;
  for (int li = 0; li < U.counts.x; ++li) {
    float t_base = intersect_shell(R, ground_alt, U.layers[li].altitude.x, mu_s).y;
    float t_top = intersect_shell(R, ground_alt, U.layers[li].altitude.y, mu_s).y;
    if (t_top <= 0.0) continue;
    t_base = max(t_base, 0.0);
    float dt = (t_top - t_base) / float(n);
    for (int j = 0; j < n; ++j) {
      vec3 x = p + sun * (t_base + (float(j) + 0.5) * dt);
      tau += cloud_extinction(li, x, altitude_of(x, R, U.planet.y), false) * dt;
    }
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

// Aerial perspective lookup: in-scatter (unit sun) and transmittance to distance t along
// the pixel with normalised device coordinates ndc.
// Slices sit at d_max (k / (n - 1))^2, so the slice coordinate is interpolated linearly in
// distance between the two neighbouring slices (linear in k would overestimate the
// in-scatter by up to 8 % near the camera).
void aerial_perspective(vec2 ndc, float t, out vec3 inscatter, out vec3 transmittance) {
  vec3 n = vec3(textureSize(ap_inscatter, 0));
  float k = sqrt(saturate(t / U.ap_params.x)) * (n.z - 1.0);
  float k0 = min(floor(k), n.z - 2.0);
  float d0 = U.ap_params.x * (k0 / (n.z - 1.0)) * (k0 / (n.z - 1.0));
  float d1 = U.ap_params.x * ((k0 + 1.0) / (n.z - 1.0)) * ((k0 + 1.0) / (n.z - 1.0));
  k = k0 + saturate((t - d0) / max(d1 - d0, 1e-3));
  vec3 tc = vec3((ndc * 0.5 + 0.5) * (n.xy - 1.0) + 0.5, k + 0.5) / n;
  inscatter = textureLod(ap_inscatter, tc, 0.0).rgb;
  transmittance = textureLod(ap_transmittance, tc, 0.0).rgb;
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(out_image);
  if (any(greaterThanEqual(px, size))) return;
  vec2 ndc = ((vec2(px) + 0.5) / vec2(size)) * 2.0 - 1.0;
  ndc.y = -ndc.y;  // row 0 is the top of the image
  vec3 dir = normalize(U.camera_forward.xyz + ndc.x * U.view.x * U.camera_right.xyz +
                       ndc.y * U.view.y * U.camera_up.xyz);
  float R = U.planet.x, h = U.planet.y, ground_alt = U.planet.z;
  vec3 sun = U.sun_dir.xyz;
  vec3 E_sun = U.sun_irradiance.rgb;
  float mu = dir.z;
  float cos_view_sun = dot(dir, sun);

  vec2 g = intersect_shell(R, h, ground_alt, mu);
  bool hits_ground = g.x >= 0.0;
  float t_ground = hits_ground ? g.x : 1e30;
  float t_limit = min(t_ground, U.planet.w);

  // ---- cloud intervals along the ray, sorted by distance
  // Steps are uniform in u = ln(t + t_ref) when t_ref = ms_params.w > 0 (step length
  // grows in proportion to distance, like the pixel footprint: fine near the camera,
  // coarse far away), and uniform in t when t_ref = 0 (the naive march).
  float t_ref = U.ms_params.w;
  Interval iv[MAX_INTERVALS];
  int n_iv = 0;
  float total_len = 0.0;  // in u (or t) units
  for (int li = 0; li < U.counts.x; ++li) {
    Interval a, b;
    int n = layer_intervals(li, mu, t_limit, a, b);
    if (n >= 1) { iv[n_iv++] = a; total_len += march_coordinate(a.t1, t_ref) - march_coordinate(a.t0, t_ref); }
    if (n == 2) { iv[n_iv++] = b; total_len += march_coordinate(b.t1, t_ref) - march_coordinate(b.t0, t_ref); }
  }
  for (int i = 1; i < n_iv; ++i) {  // insertion sort
    Interval x = iv[i];
    int j = i - 1;
    while (j >= 0 && iv[j].t0 > x.t0) { iv[j + 1] = iv[j]; --j; }
    iv[j + 1] = x;
  }

  // ---- march the clouds
  vec3 C = vec3(0.0);  // in-scattered radiance from clouds
  float T = 1.0;       // cloud transmittance
  float depth_acc = 0.0;
  if (n_iv > 0) {
    float jitter = hash12(uvec2(px) + uvec2(U.counts.y * 7919, U.counts.y * 104729));
    float nominal_du = total_len / U.quality.x;
    for (int k = 0; k < n_iv && T > CLOUD_T_EPS; ++k) {
      int li = iv[k].layer;
      CloudLayerGpu L = U.layers[li];
      float u0 = march_coordinate(iv[k].t0, t_ref), u1 = march_coordinate(iv[k].t1, t_ref);
      int steps = max(1, int(ceil((u1 - u0) / max(nominal_du, 1e-6))));
      float du = (u1 - u0) / float(steps);
      for (int s = 0; s < steps && T > CLOUD_T_EPS; ++s) {
        // step [ta, tb] around the jittered sample t
        float ta = march_distance(u0 + float(s) * du, t_ref);
        float tb = march_distance(u0 + float(s + 1) * du, t_ref);
        float t = march_distance(u0 + (float(s) + jitter) * du, t_ref);
        float dt = tb - ta;
        vec3 p = t * dir;
        float alt = altitude_of(p, R, h);
        float coverage;
        float sigma = cloud_extinction(li, p, alt, true, coverage);
        if (sigma <= 0.0) continue;
        vec3 up = up_at(p, R, h);
        float mu_s = dot(up, sun);
        vec3 T_atm = transmittance_to_space(alt, mu_s);
        // direct sun: Wrenninge octaves over the light-march optical depth
        vec3 L_sun = vec3(0.0);
        if (max(T_atm.r, max(T_atm.g, T_atm.b)) > 0.0) {
          float tau = light_optical_depth(li, p, alt, sun, mu_s);
          float s_sum = 0.0, a = 1.0, b = 1.0, c = 1.0;
          for (int o = 0; o < int(U.quality.z); ++o) {
            s_sum += b * cloud_phase(cos_view_sun, L.optics.y, L.optics.z, L.optics.w, L.optics2.x, c) * exp(-a * tau);
            a *= U.ms_params.x; b *= U.ms_params.y; c *= U.ms_params.z;
          }
          L_sun = E_sun * T_atm * s_sum;
        }
        vec3 L_diffuse = diffuse_inscatter(L, alt, mu_s, T_atm, coverage, E_sun, ground_alt);
        float absorbed = one_minus_exp_neg(sigma * dt);  // albedo 1: scattered fraction
        C += T * absorbed * (L_sun + L_diffuse);
        depth_acc += t * T * absorbed;
        T *= 1.0 - absorbed;
      }
    }
  }

  // ---- background: ground or sky
  vec3 background;
  if (hits_ground) {
    vec3 p = t_ground * dir;
    vec3 up = up_at(p, R, h);
    float mu_s = dot(up, sun);
    vec3 T_atm = transmittance_to_space(ground_alt, mu_s);
    float tau = 0.0;
    if (mu_s > 0.0 && U.counts.x > 0) tau = ground_shadow_optical_depth(p, ground_alt, sun, mu_s);
    float direct = exp(-tau);
    float diffuse = slab_diffuse_transmittance(tau * max(mu_s, 0.0));
    vec3 E = E_sun * (T_atm * max(mu_s, 0.0) * max(direct, diffuse) + sky_irradiance(ground_alt, mu_s) * diffuse);
    vec3 L_ground = U.ground_albedo.rgb / PI * E;
    vec3 ap_in, ap_T;
    aerial_perspective(ndc, t_ground, ap_in, ap_T);
    background = L_ground * ap_T + E_sun * ap_in;
  } else {
    float r = atmo_radius(h);
    // direction relative to the sun's azimuth: x towards the sun's horizontal direction
    vec2 sun_h = sun.xy;
    float sl = length(sun_h);
    vec2 ax = sl > 1e-6 ? sun_h / sl : vec2(1.0, 0.0);
    vec3 d_rel = vec3(dot(dir.xy, ax), dot(dir.xy, vec2(-ax.y, ax.x)), dir.z);
    background = E_sun * textureLod(sky_view_lut, sky_view_uv(d_rel, r, vec2(textureSize(sky_view_lut, 0))), 0.0).rgb;
    if (cos_view_sun > U.sun_dir.w) {
      float solid_angle = 2.0 * PI * (1.0 - U.sun_dir.w);
      background += E_sun / solid_angle * transmittance_to_space(h, mu);
    }
    background += vec3(U.ground_albedo.w);
  }

  // ---- aerial perspective on the clouds at their transmittance-weighted depth
  float opacity = 1.0 - T;
  if (opacity > 0.0) {
    float t_mean = depth_acc / opacity;
    vec3 ap_in, ap_T;
    aerial_perspective(ndc, t_mean, ap_in, ap_T);
    C = C * ap_T + opacity * E_sun * ap_in;
  }
  vec3 radiance = C + T * background;

  if (any(isnan(radiance)) || any(isinf(radiance)) || any(lessThan(radiance, vec3(0.0)))) {
    atomicAdd(counters.nonfinite_pixels, 1u);
    radiance = vec3(0.0);
  }
  if (U.counts.z != 0) atomicAdd(counters.density_evals, g_density_evals);
  if (opacity > 0.01) atomicAdd(counters.cloud_pixels, 1u);
  imageStore(out_image, px, vec4(radiance, opacity));
}
