#version 450 core
// One frame, composited at full resolution: the resolved cloud buffer (cloud_march.comp,
// cloud_resolve.comp; aerial perspective already applied there) over the sky (sky-view LUT
// + sun disk) or the ground (lit by sun and sky, shadowed by the clouds' optical depth from
// the ground shadow map, seen through the aerial perspective). Output: linear spectral radiance at 680/550/440 nm
// (W m^-2 sr^-1 nm^-1) in rgb, cloud opacity (1 - cloud transmittance) in a.
// Compiled with CLOUDSVC_GROUND_SHADOWS_PER_PIXEL (CompositePass, for qualities without the
// ground shadow map), the shadows are marched through the cloud density at every ground
// pixel instead; without it the program holds no density code, which llvmpipe would run
// for every pixel whether a pixel marches or not (docs/PERFORMANCE.md).
#include "common.glsl"
#include "frame_counters.glsl"
#include "frame_uniforms.glsl"
#include "temporal_uniforms.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "sky_view_mapping.glsl"
#include "horizon_split.glsl"
#include "ground_shadow_map.glsl"
#include "phase_function.glsl"
// (before the #ifdef: the #include expansion inserts each file once, where first named)
#include "slab_transmittance.glsl"
#include "weather_map_sampling.glsl"
#include "ground_albedo.glsl"
#ifdef CLOUDSVC_GROUND_SHADOWS_PER_PIXEL
#include "cloud_density.glsl"
#include "cloud_lighting.glsl"
#endif
#include "aerial_perspective_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
const float BACKGROUND_T_EPS = 1e-3;  // = CLOUD_T_EPS of cloud_march.comp
layout(rgba32f, binding = IMG_FRAME_OUT) uniform writeonly image2D out_image;
layout(binding = TEX_SKY_VIEW_LUT) uniform sampler2D sky_view_lut;
layout(binding = TEX_CLOUD_RADIANCE) uniform sampler2D cloud_radiance;  // resolved cloud buffer (temporal_uniforms.glsl)
layout(binding = TEX_CLOUD_DEPTH) uniform sampler2D cloud_depth;        // ... its depth, ground-share shift, layer


// The cloud-buffer texels that make frame pixel px (n of them: 1 at divisor 1, else 4)
// and their weights: at divisor 1 its own pixel; else the four nearest cloud pixels
// weighted bilinearly and by how alike their background distance is to this pixel's
// t_background (depth-aware upsampling: cloud over the horizon does not bleed onto the
// ground).
int cloud_taps(ivec2 px, float t_background, out ivec2 cs[4], out float ws[4]) {
  int r = temporal.cloud_divisor;
  if (r == 1) {
    cs[0] = px;
    ws[0] = 1.0;
    return 1;
  }
  vec2 c = (vec2(px) + 0.5) / float(r) - 0.5;
  ivec2 c0 = clamp(ivec2(floor(c)), ivec2(0), temporal.cloud_buffer_size - 1);
  ivec2 c1 = min(c0 + 1, temporal.cloud_buffer_size - 1);
  vec2 f = clamp(c - vec2(c0), 0.0, 1.0);
  cs = ivec2[4](c0, ivec2(c1.x, c0.y), ivec2(c0.x, c1.y), c1);
  float bilinear[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  float wsum = 0.0;
  for (int i = 0; i < 4; ++i) {
    vec3 d = view_ray(cloud_pixel_ndc(vec2(cs[i])));
    vec2 g = intersect_shell(frame.shell_radius_m, frame.camera_altitude_m, frame.ground_altitude_m, d.z);
    float t_i = g.x >= 0.0 ? g.x : 1e30;
    float likeness = t_background >= 1e29 || t_i >= 1e29 ? (t_background == t_i ? 1.0 : 1e-3)
                                                          : 1.0 / (1.0 + 8.0 * abs(t_i - t_background) / t_background);
    ws[i] = bilinear[i] * likeness + 1e-6;
    wsum += ws[i];
  }
  for (int i = 0; i < 4; ++i) ws[i] /= wsum;
  return 4;
}

// The cloud buffer at frame pixel px: radiance the clouds send to the camera (aerial
// perspective included, cloud_march.comp) and their transmittance.
vec4 cloud_at(ivec2 px, float t_background) {
  ivec2 cs[4];
  float ws[4];
  int n = cloud_taps(px, t_background, cs, ws);
  vec4 a = vec4(0.0);
  for (int i = 0; i < n; ++i) a += ws[i] * texelFetch(cloud_radiance, cs[i], 0);
  return a;
}

// The clouds' shift of the ground's share of the background seen through them at frame
// pixel px (cloud_march.comp; read only where the horizon crosses the pixel).
float share_shift_at(ivec2 px, float t_background) {
  ivec2 cs[4];
  float ws[4];
  int n = cloud_taps(px, t_background, cs, ws);
  float shift = 0.0;
  for (int i = 0; i < n; ++i) shift += ws[i] * texelFetch(cloud_depth, cs[i], 0).y;
  return shift;
}

// Mean radiance of the sun disk over the pixel of view ray dir (W m^-2 sr^-1 nm^-1), from
// altitude h: the disk has uniform radiance E_sun T / Omega (Omega = 2 pi (1 - cos rho),
// rho = 0.2667 deg); the pixel is a box filter of angular width p along the camera's right
// and up (p = 2 tan(hfov/2) / width at the centre, times cos^2 of the angle off the axis),
// and the disk is taken as the square of the same solid angle in the tangent plane: the
// result is L Omega_overlap / p^2. It varies continuously with the pose (a disk smaller
// than a pixel neither blinks nor jumps a pixel at a time), keeps the disk's irradiance
// E_sun T over the image, and equals L inside a disk larger than the pixels.
vec3 sun_disk(vec3 dir, float h) {
  vec3 sun = frame.sun_direction;
  float omega = 2.0 * PI * (1.0 - SUN_COS_ANGULAR_RADIUS);
  float side = sqrt(omega);
  float axis = dot(dir, frame.camera_forward);
  float p = 2.0 * frame.tan_half_fov_x / frame.image_size_px.x * axis * axis;
  float c = dot(dir, sun);
  if (c < cos(0.7072 * (side + p))) return vec3(0.0);  // no overlap possible
  vec3 offset = sun - c * dir;  // tangent-plane offset of the disk centre (rad, small angles)
  float ex = dot(offset, frame.camera_right), ey = dot(offset, frame.camera_up);
  float ox = max(0.0, min(ex + 0.5 * side, 0.5 * p) - max(ex - 0.5 * side, -0.5 * p));
  float oy = max(0.0, min(ey + 0.5 * side, 0.5 * p) - max(ey - 0.5 * side, -0.5 * p));
  return SOLAR_IRRADIANCE / omega * transmittance_to_space(h, sun.z) * (ox * oy / (p * p));
}

// Radiance of the ground seen along dir, which hits it at distance t_ground (W m^-2 sr^-1
// nm^-1): lit by the sun through the clouds' optical depth above the ground point (ground
// shadow map, or marched per pixel) and by the sky, seen through the aerial perspective.
vec3 ground_radiance(vec3 dir, float t_ground) {
  float R = frame.shell_radius_m, h = frame.camera_altitude_m, ground_alt = frame.ground_altitude_m;
  vec3 sun = frame.sun_direction;
  vec3 E_sun = SOLAR_IRRADIANCE;
  vec3 p = t_ground * dir;
  vec3 up = up_at(p, R, h);
  float mu_s = dot(up, sun);
  vec3 T_atm = transmittance_to_space(ground_alt, mu_s);
  float tau = 0.0;  // cloud optical depth above the ground point, towards the sun
#ifdef CLOUDSVC_GROUND_SHADOWS_PER_PIXEL
  if (shadow.march_per_pixel != 0 && mu_s > 0.0)
    for (int li = 0; li < frame.layer_count; ++li)
      tau += layer_shadow_optical_depth(li, p, ground_alt, sun, mu_s, frame.ground_shadow_steps);
#else
  if (shadow.map_valid != 0 && mu_s > 0.0)
    for (int li = 0; li < frame.layer_count; ++li)
      tau += shadow_map_optical_depth(li, p);
#endif
  // sun through the clouds: the slab's beam transmittance at their vertical optical depth
  // (direct + forward-scattered + diffuse); sky light: the diffuse one; and the round trips
  // between the ground and the clouds' base (ground_cloud_gain); the albedo where the
  // ground point is (ground_albedo_at)
  float tau_v = tau * max(mu_s, 0.0);
  float sun_through = mu_s > 0.0 ? slab_beam_transmittance(tau_v, max(mu_s, 0.05)) : 0.0;
  vec3 albedo = ground_albedo_at(from_shell_centre(p));
  vec3 E = E_sun * (T_atm * max(mu_s, 0.0) * sun_through + sky_irradiance(ground_alt, mu_s) * slab_diffuse_transmittance(tau_v)) *
           ground_cloud_gain(albedo, tau_v);
  vec3 L_ground = albedo / PI * E;
  vec3 ap_in, ap_T;
  aerial_perspective(dir, t_ground, ap_in, ap_T);
  return L_ground * ap_T + E_sun * ap_in;
}

// Radiance of the sky along dir (sky-view LUT; the sun disk is added separately).
vec3 sky_radiance(vec3 dir) {
  vec3 sun = frame.sun_direction;
  float r = atmo_radius(frame.camera_altitude_m);
  // direction relative to the sun's azimuth: x towards the sun's horizontal direction
  vec2 sun_h = sun.xy;
  float sl = length(sun_h);
  vec2 ax = sl > 1e-6 ? sun_h / sl : vec2(1.0, 0.0);
  vec3 d_rel = vec3(dot(dir.xy, ax), dot(dir.xy, vec2(-ax.y, ax.x)), dir.z);
  return SOLAR_IRRADIANCE * textureLod(sky_view_lut, sky_view_uv(d_rel, r, vec2(textureSize(sky_view_lut, 0))), 0.0).rgb +
         vec3(NIGHT_SKY_RADIANCE);
}

// A pixel's background split at the horizon: the fraction f_ground of its footprint below it
// (box filter) and the rays the ground part (hitting the ground at t_g) and the sky part are
// seen along. Away from the horizon: all ground or all sky along the centre ray dir. The
// ground part is seen along a ray at least a quarter of the pixel's elevation range below
// the horizon, the sky part at least as far above it: both vary continuously with the pose
// and equal the centre ray once the pixel is all ground or all sky.
struct HorizonSplit {
  float f_ground;
  vec3 dir_g;
  float t_g;
  vec3 dir_s;
};

HorizonSplit split_at_horizon(vec2 ndc, vec2 half_px, vec3 dir, bool hits_ground, float t_ground) {
  HorizonSplit hs = HorizonSplit(hits_ground ? 1.0 : 0.0, dir, t_ground, dir);
  HorizonFootprint fp = footprint_at_horizon(ndc, half_px, dir);
  if (!crosses_horizon(fp)) return hs;
  float margin = 0.25 * (fp.e_hi - fp.e_lo);
  float e_c = asin(clamp(dir.z, -1.0, 1.0));
  vec3 g_dir = at_elevation(dir, min(e_c, fp.e_h - margin));
  vec2 gg = intersect_shell(frame.shell_radius_m, frame.camera_altitude_m, frame.ground_altitude_m, g_dir.z);
  if (gg.x < 0.0) return hs;
  hs.f_ground = fp.f_ground;
  hs.dir_g = g_dir;
  hs.t_g = gg.x;
  hs.dir_s = at_elevation(dir, max(e_c, fp.e_h + margin));
  return hs;
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(out_image);
  if (any(greaterThanEqual(px, size))) return;
  vec2 ndc = ((vec2(px) + 0.5) / vec2(size)) * 2.0 - 1.0;
  ndc.y = -ndc.y;  // row 0 is the top of the image
  vec3 dir = view_ray(ndc);
  float R = frame.shell_radius_m, h = frame.camera_altitude_m, ground_alt = frame.ground_altitude_m;
  float mu = dir.z;

  vec2 g = intersect_shell(R, h, ground_alt, mu);
  bool hits_ground = g.x >= 0.0;
  float t_ground = hits_ground ? g.x : 1e30;

  vec4 cloud = cloud_at(px, t_ground);  // rgb: radiance from the clouds through the air in front; a: their transmittance
  HorizonSplit hs = split_at_horizon(ndc, vec2(1.0, -1.0) / vec2(size), dir, hits_ground, t_ground);
  // The ground's share of the background seen through the clouds: all or nothing away from
  // the horizon; across it, the area below the horizon shifted by the clouds (the cloud
  // buffer's share shift: the march weighs each side of the footprint by its area and by
  // the transmittance of the clouds along its own rays; a cloud above the horizon hides the
  // sky part only)
  float ground_share = hs.f_ground <= 0.0 ? 0.0 : hs.f_ground >= 1.0 ? 1.0 : clamp(hs.f_ground + share_shift_at(px, t_ground), 0.0, 1.0);

  // ---- background: ground and/or sky, faded out behind clouds as their transmittance
  // falls from twice to once the march's early-exit threshold (the march drops the clouds
  // behind at that level too; the fade keeps the image continuous) and skipped below it;
  // the sun disk, bright enough to show through them, always (over the sky part)
  float T = clamp(cloud.a, 0.0, 1.0);
  float background_weight = saturate(T / BACKGROUND_T_EPS - 1.0);
  vec3 background = vec3(0.0);
  if (background_weight > 0.0) {
    if (ground_share > 0.0) background += ground_share * ground_radiance(hs.dir_g, hs.t_g);
    if (ground_share < 1.0) background += (1.0 - ground_share) * sky_radiance(hs.dir_s);
  }
  vec3 sun_seen = ground_share < 1.0 ? (1.0 - ground_share) * sun_disk(dir, h) : vec3(0.0);
  float opacity = 1.0 - T;
  vec3 radiance = cloud.rgb + T * (background_weight * background + sun_seen);

  if (any(isnan(radiance)) || any(isinf(radiance)) || any(lessThan(radiance, vec3(0.0)))) {
    atomicAdd(counters.nonfinite_pixels, 1u);
    radiance = vec3(0.0);
    opacity = 0.0;
  }
  if (opacity > CLOUD_PIXEL_OPACITY) atomicAdd(counters.cloud_pixels, 1u);
#ifdef CLOUDSVC_GROUND_SHADOWS_PER_PIXEL
  if (frame.count_density_evaluations != 0 && g_density_evals > 0u) atomicAdd(counters.density_evals, g_density_evals);
#endif
  imageStore(out_image, px, vec4(radiance, opacity));
  count_if_loops_capped();
}
