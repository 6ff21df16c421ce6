#version 450 core
// The cloud march: for this frame's fresh cloud pixels (every stride-th, see
// temporal_uniforms.glsl), the clouds along the ray through the layer intervals. Output
// (fresh_radiance) rgb: radiance the clouds send to the camera, in-scattered in the clouds and
// seen through the aerial perspective in front of them (W m^-2 sr^-1 nm^-1, 680/550/440
// nm), a: cloud transmittance; (fresh_depth) x: depth (m; the
// transmittance-weighted cloud distance, or clear_ray_depth() when it meets no cloud), y:
// how much the clouds shift the ground's share of the background seen through them from
// the pixel's area below the horizon (0 unless the horizon crosses the pixel; see main),
// z: layer of that depth (-1 none), w: the sample's weight.
#include "common.glsl"
#include "frame_counters.glsl"
#include "frame_uniforms.glsl"
#include "temporal_uniforms.glsl"
#include "atmosphere_model.glsl"
#include "atmosphere_lookup.glsl"
#include "phase_function.glsl"
#include "weather_map_sampling.glsl"
#include "ground_albedo.glsl"
#include "cloud_density.glsl"
#include "cloud_intervals.glsl"
#include "coverage_pyramid.glsl"
#include "cloud_lighting.glsl"
#include "ground_shadow_map.glsl"
#include "layers_above.glsl"
#include "light_volume.glsl"
#include "column_volume.glsl"
#include "aerial_perspective_lookup.glsl"
#include "horizon_split.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = IMG_FRESH_RADIANCE_OUT) uniform writeonly image2D fresh_radiance;
layout(rgba32f, binding = IMG_FRESH_DEPTH_OUT) uniform writeonly image2D fresh_depth;

const float CLOUD_T_EPS = 1e-3;  // early exit below this cloud transmittance
// ... but rays that may see the sun's disk march on to this one: the disk is ~1e5 times as
// bright as a lit cloud (2.8e4 against ~0.2 W m^-2 sr^-1 nm^-1) and shows through a cloud
// until its optical depth passes ~12, where the sky and ground behind are lost at 7
// (composite.comp adds the disk times T always). At 1e-8 what is left of the disk is 1 % of a
// dim cloud's radiance.
const float SUN_T_EPS = 1e-8;
// With the column depths, a step of optical depth above SKIN_TAU (at its sample) seen
// through a cloud transmittance above SKIN_T_MIN is read at SKIN_SUBSTEPS points and lit
// once where its light comes from (march_ray). Against the reference's columns
// (docs/ACCURACY.md, "Column depths"): 8 points gained at most 1.2 dB over 4, a threshold
// of 0.25 nothing over 0.5; leaving the steps behind T = 0.25 to one sample, as before,
// cost no accuracy measured and 71 % fewer sub-sample evaluations (29.5 -> 17.9 per pixel
// in all, tests/render_column_depths_test.cpp).
const int SKIN_SUBSTEPS = 4;
const float SKIN_TAU = 0.5;
const float SKIN_T_MIN = 0.25;
// Primary steps per coverage-pyramid query (coverage_pyramid.glsl): a run this long whose
// map footprint the pyramid clears is skipped without a density evaluation.
const int PYRAMID_RUN = 8;
// Distance (m) over which the ground irradiance under a cloud sample is held: the sun's
// zenith angle at the ground below moves by 1.6e-3 rad over it (10 km / 6371 km).
const float GROUND_IRRADIANCE_SPACING = 10000.0;

// Can the points of the ray (local frame, from the camera) between distances ta and tb
// have cloud of layer li? False only where the pyramid bounds the layer's local coverage
// to 0 over a cap holding the whole segment: centred on its midpoint's direction, of
// angular radius asin(L / |M|) <= L / (|M| - L) (L half its length, |M| the midpoint's
// distance from the shell centre) plus 1e-5 rad (~60 m) for float rounding.
bool segment_may_have_cloud(int li, vec3 dir, float ta, float tb) {
  vec3 q = from_shell_centre(0.5 * (ta + tb) * dir);
  float half_len = 0.5 * (tb - ta);
  float a = half_len / max(length(q) - half_len, 1.0) + 1e-5;
  vec2 ll = map_lat_lon(q);
  float m = pyramid_max_in_cap(ll.x, ll.y, a);
  return local_coverage(frame.layers[li], vec4(m)) > 0.0;
}

// The depth (m) stored for a ray that meets no cloud, by which the resolve finds where the
// pixel looked last frame (cloud_resolve.comp): where the ray enters the first layer it
// crosses, the nearest point a cloud could be; from a camera inside that layer (entry at 0,
// the camera itself, which projects onto no pixel of the previous camera and would leave
// the clear pixel without history, to be filled with its fresh neighbours' cloud every
// frame), where the ray leaves it: the far end of the clear span. (A ray that crosses no
// layer stores the ground's or the march reach's distance.)
float clear_ray_depth(Interval first) { return first.t0 > 0.0 ? first.t0 : first.t1; }

// Light steps at distance t: the full count while the pixel footprint is finer than a
// base-noise texel, falling in proportion beyond (no finer lighting than the pixel can
// show), to a third at most (level of detail by the ray's cone footprint).
int light_steps_at(float t, CloudLayerGpu L) {
  int n = frame.light_steps;
  if (frame.level_of_detail == 0) return n;
  float texel = 1.0 / (L.base_noise_frequency * float(textureSize(base_noise, 0).x));  // base-noise texel, m
  float k = clamp(texel / max(t * frame.pixel_angle_rad, 1e-3), 1.0 / 3.0, 1.0);
  return max(2, int(ceil(float(n) * k)));
}

// Detail noise at distance t: sampled while a pixel spans less than two detail texels,
// else replaced by its mean.
int detail_mode_at(float t, CloudLayerGpu L) {
  if (frame.level_of_detail == 0) return DETAIL_SAMPLED;
  float texel = 1.0 / (L.detail_noise_frequency * float(textureSize(detail_noise, 0).x));
  return t * frame.pixel_angle_rad < 2.0 * texel ? DETAIL_SAMPLED : DETAIL_MEAN;
}

// Weight of the pixel-centre ray in a still camera's running average of footprint samples
// (cloud_resolve.comp), in units of one jittered sample. The centre is the midpoint rule
// for the pixel's box filter: exact for radiance varying linearly across the pixel, where
// one uniformly placed point errs by its offset times the gradient; at an edge inside the
// pixel both are one Bernoulli draw. So the centre is worth at least one random point;
// counting it twice keeps the first cycle's (centre + one point) estimate from taking half
// of a random point's error, and the exponential blend (RenderQuality::history_blend_min)
// forgets it as jittered points arrive. Measured over random scene sets (docs/ACCURACY.md).
const float CENTRE_SAMPLE_WEIGHT = 2.0;

// The clouds along one ray dir of cloud pixel q.
struct RaySample {
  vec3 C;       // radiance the clouds send to the camera, aerial perspective included
  float T;      // their transmittance
  float depth;  // transmittance-weighted cloud distance (m), or clear_ray_depth()
  int layer;    // layer of that depth (-1 none)
};

RaySample march_ray(ivec2 q, vec3 dir, float column_offset) {
  float R = frame.shell_radius_m, h = frame.camera_altitude_m, ground_alt = frame.ground_altitude_m;
  vec3 sun = frame.sun_direction;
  vec3 E_sun = SOLAR_IRRADIANCE;
  float mu = dir.z;
  float cos_view_sun = dot(dir, sun);
  // the early exit's transmittance: lower for rays within 4 cloud pixels of the sun's disk
  // (a pixel's angle at the image centre, the largest, times the cloud buffer's divisor)
  float pixel_rad = 2.0 * frame.tan_half_fov_x / frame.image_size_px.x * float(temporal.cloud_divisor);
  float t_eps = cos_view_sun > cos(acos(SUN_COS_ANGULAR_RADIUS) + 4.0 * pixel_rad) ? SUN_T_EPS : CLOUD_T_EPS;

  vec2 g = intersect_shell(R, h, ground_alt, mu);
  bool hits_ground = g.x >= 0.0;
  float t_ground = hits_ground ? g.x : 1e30;
  // the view's near and far planes (cloud_clip in view_request.h)
  float cos_axis = max(dot(dir, frame.camera_forward), 1e-6);
  float t_start = frame.view_near_m / cos_axis;
  float t_limit = min(t_ground, frame.march_reach_m);
  float t_clip_end = min(t_limit, frame.view_far_m / cos_axis);

  // Steps are uniform in u = ln(1 + t / t_ref) (t_ref = ms_params.w > 0) or in t (0: the
  // naive march). In empty air the march probes with steps long_step times longer
  // (Schneider 2015); a probe asks whether the span since the last sample can hold cloud
  // anywhere (cloud_may_be_on_segment: a bound, so no cloud between probes is missed), and
  // if so the march steps back and re-marches the span at the normal step; it returns to
  // long steps after long_step empty samples.
  float t_ref = frame.step_growth_ref_m;
  Interval iv[MAX_INTERVALS];
  float total_len;
  int n_iv = ray_intervals(mu, t_start, t_clip_end, t_ref, iv, total_len);
  int long_step = max(1, int(frame.long_step_factor));
  // the diffuse light from each point's own column (RenderQuality::column_steps): thick
  // steps are sub-sampled (SKIN_SUBSTEPS)
  bool columns = shadow.column_valid != 0 || shadow.column_march_steps > 0;

  vec3 C = vec3(0.0);  // in-scattered radiance from clouds
  float T = 1.0;       // cloud transmittance
  float depth_acc = 0.0;
  float depth = n_iv > 0 ? clear_ray_depth(iv[0]) : min(t_limit, 1e7);
  int depth_layer = n_iv > 0 ? iv[0].layer : -1;
  float strongest = 0.0;  // largest single-step contribution T * absorbed, and its layer
  int cloud_layer = -1;
  // cloud_free_ground_irradiance and the ground's albedo below, evaluated at the first
  // cloud sample and again every GROUND_IRRADIANCE_SPACING along the ray (at
  // t_ground_irradiance)
  vec3 ground_sun = vec3(0.0), ground_sky = vec3(0.0), ground_albedo = frame.ground_albedo.rgb;
  float t_ground_irradiance = -1e30;
  if (n_iv > 0) {
    float jitter = hash12(uvec2(q) + uvec2(frame.frame_index * 7919, frame.frame_index * 104729));
    float nominal_du = total_len / float(frame.primary_steps);
    for (int k = 0; k < n_iv && T > t_eps; ++k) {
      int li = iv[k].layer;
      CloudLayerGpu L = frame.layers[li];
      // light marches stop where the sun's peak beam towards the camera is spent
      // (RenderQuality::light_march_cutoff): past the frame's cut-off, and earlier where
      // this view's scattering angle bounds it below PEAK_BEAM_NEGLIGIBLE times the
      // horizontal solar flux (the diffuse light scales with it; sun.z: mu_s at the camera)
      float light_cut = frame.light_march_cutoff_tau < 1e29
                            ? min(frame.light_march_cutoff_tau,
                                  peak_beam_cutoff_tau(cos_view_sun, L.g_hg, L.g_d, L.draine_alpha, L.w_d,
                                                       PEAK_BEAM_NEGLIGIBLE * max(sun.z, 0.05)))
                            : frame.light_march_cutoff_tau;
      // does any layer lie above this one (layers_above.glsl)?
      bool layers_above = false;
      for (int lj = 0; lj < frame.layer_count; ++lj)
        layers_above = layers_above || layer_is_above(lj, li);
      float u0 = march_coordinate(iv[k].t0, t_ref), u1 = march_coordinate(iv[k].t1, t_ref);
      // with steps growing with distance (t_ref > 0), a near layer's share of the budget
      // can leave a far one a few steps: every layer crossing gets at least a quarter of
      // the primary steps (its own structure does not depend on the air in front of it)
      int steps = max(1, int(ceil((u1 - u0) / max(nominal_du, 1e-6))));
      if (t_ref > 0.0) steps = max(steps, frame.primary_steps / 4);
      float du = (u1 - u0) / float(steps);
      // st: step index; in probing mode the probe at st covers (st - long_step, st]
      int st = 0, last_fine = -1, empty_run = 0;
      bool probing = long_step > 1;
      // coverage pyramid (frame.coverage_pyramid): only for a layer the map can clear at all (a layer
      // above 6/11 coverage never clears: no queries); next_query: the first step not yet
      // covered by a query
      bool pyramid = frame.coverage_pyramid != 0 && local_coverage(L, vec4(0.0)) <= 0.0;
      int next_query = 0;
      for (int guard = 0; st < steps && T > t_eps && guard < 3 * steps + 4; ++guard) {
        if (pyramid && st >= next_query) {
          // the samples of steps st .. st + PYRAMID_RUN - 1 lie between these distances
          next_query = min(st + PYRAMID_RUN, steps);
          float ta = march_distance(u0 + float(st) * du, t_ref), tb = march_distance(u0 + float(next_query) * du, t_ref);
          if (!segment_may_have_cloud(li, dir, ta, tb)) {
            // no cloud there: skip the run; the span before it is known empty, so a probe
            // that finds cloud after it steps back no further than its end
            st = next_query;
            last_fine = st - 1;
            empty_run = 0;
            probing = long_step > 1;
            continue;
          }
        }
        float t = march_distance(u0 + (float(st) + jitter) * du, t_ref);
        vec3 p = t * dir;
        float alt = altitude_of(p, R, h);
        vec4 w = layer_weather_at(li, p);
        if (probing) {
          // the probe covers the samples st - long_step + 1 .. st (those not yet marched):
          // any cloud on that stretch sends the march back over it at the normal step
          g_density_evals += 1u;
          float t_back = march_distance(u0 + (float(max(st - long_step + 1, last_fine + 1)) + jitter) * du, t_ref);
          if (cloud_may_be_on_segment(li, t_back * dir, p, w)) {
            probing = false;  // step back: re-march the probed span at the normal step
            empty_run = 0;
            st = max(st - long_step + 1, last_fine + 1);
          } else {
            st = st == steps - 1 ? steps : min(st + long_step, steps - 1);
          }
          continue;
        }
        float coverage;
        float sigma = cloud_extinction_in(li, p, alt, detail_mode_at(t, L), w, coverage);
        last_fine = st;
        if (sigma <= 0.0) {
          if (long_step > 1 && ++empty_run >= long_step) {
            probing = true;
            st = min(st + long_step, steps - 1);
            if (st == last_fine) st = steps;
          } else {
            ++st;
          }
          continue;
        }
        empty_run = 0;
        float ta = march_distance(u0 + float(st) * du, t_ref);
        float tb = march_distance(u0 + float(st + 1) * du, t_ref);
        ++st;
        float dt = tb - ta;
        float absorbed = one_minus_exp_neg(sigma * dt);  // albedo 1: scattered fraction
        if (columns && sigma * dt > SKIN_TAU && T > SKIN_T_MIN) {
          // An optically thick step under the column depths: the light of a cloud's lit
          // skin changes within metres of depth (the optical depth above a point starts at
          // 0 at the cloud's top), and one sample at a random point of a step hundreds of
          // metres long lands in it or misses it at random. So the step's extinction is
          // read at SKIN_SUBSTEPS points (each at the step's jitter within its sub-step),
          // which give the step's opacity, and the light is evaluated once, at the mean
          // distance of the light the step scatters towards the camera (weights T_i a_i:
          // exact for light varying linearly along the step).
          float T_sub = 1.0, weight = 0.0, weighted_t = 0.0, sub = dt / float(SKIN_SUBSTEPS);
          for (int i = 0; i < SKIN_SUBSTEPS; ++i) {
            float ti = ta + (float(i) + jitter) * sub;
            vec3 pi = ti * dir;
            float ci;
            float a = one_minus_exp_neg(cloud_extinction_in(li, pi, altitude_of(pi, R, h), detail_mode_at(ti, L), w, ci) * sub);
            weight += T_sub * a;
            weighted_t += T_sub * a * ti;
            T_sub *= 1.0 - a;
          }
          if (weight > 0.0) {
            absorbed = 1.0 - T_sub;
            t = weighted_t / weight;
            p = t * dir;
            alt = altitude_of(p, R, h);
          }
        }
        vec3 up = up_at(p, R, h);
        float mu_s = dot(up, sun);
        vec3 T_atm = transmittance_to_space(alt, mu_s);
        // what the layers above let through (layers_above.glsl)
        vec3 above = layers_above
                         ? layers_above_light(layers_above_optical_depth(li, p, alt, sun, mu_s), mu_s,
                                              layer_diffuse_reflectance(L, coverage))
                         : vec3(1.0, 1.0, 0.0);
        // direct sun: the peak beam (single scattering and the light scattered only
        // through the diffraction peak) over the light-march optical depth
        vec3 L_sun = vec3(0.0);
        float tau = 0.0, marched = 0.0;  // the sun's optical depth over the marched length (m)
        if (max(T_atm.r, max(T_atm.g, T_atm.b)) > 0.0) {
          if (shadow.volume_valid != 0) {
            tau = light_volume_optical_depth(li, p, alt);
            marched = light_march_length(li, alt, mu_s);
          } else {
            tau = light_optical_depth(li, p, alt, sun, mu_s, light_steps_at(t, L), w, light_cut, marched);
          }
          vec3 s_sum = vec3(peak_beam_phase(cos_view_sun, tau, L.g_hg, L.g_d, L.draine_alpha, L.w_d));
#ifdef CLOUDSVC_MIE_PHASE
          // single scattering with the layer's Mie table per wavelength instead of the fit
          s_sum += (tabulated_phase(li, cos_view_sun) - cloud_phase(cos_view_sun, L.g_hg, L.g_d, L.draine_alpha, L.w_d)) * exp(-tau);
#endif
          L_sun = E_sun * T_atm * (above.x * s_sum);
        }
        if (abs(t - t_ground_irradiance) > GROUND_IRRADIANCE_SPACING) {
          cloud_free_ground_irradiance(ground_alt, mu_s, E_sun, ground_sun, ground_sky);
          ground_albedo = ground_albedo_at(from_shell_centre(p));
          t_ground_irradiance = t;
        }
        // the optical depths above and below the point: its own column's (the column volume,
        // or marched from the point: RenderQuality::column_volume), or a homogeneous layer's
        // of the map's coverage
        // (llvmpipe runs every branch with its lanes masked: column_march_steps is 0 unless
        // the march is the one used, so its loops cost nothing elsewhere)
        float tau_above, tau_below;
        if (shadow.column_valid != 0) {
          vec2 below_above = column_volume_depths(li, p, alt);
          tau_below = below_above.x;
          tau_above = below_above.y;
        } else if (shadow.column_march_steps > 0) {
          vec2 below_above = marched_column_depths(li, p, alt, up, w, shadow.column_march_steps, column_offset);
          tau_below = below_above.x;
          tau_above = below_above.y;
        } else {
          float sigma_nominal = L.extinction_max * L.density_scale * coverage;
          tau_above = sigma_nominal * max(L.top_m - alt, 0.0);
          tau_below = sigma_nominal * max(alt - nominal_base_m(L), 0.0);
        }
        // the sun's slab: tilted towards the sun (RenderQuality::sun_slab_tilt) or the
        // column's horizontal one; the scattered light travels along -dir
        SunSlab sun_slab = frame.sun_slab_tilt != 0
                               ? tilted_sun_slab(vec2(tau_below, tau_above), tau,
                                                 sun_window(marched, mu_s, L.top_m - alt), up, sun, -dir)
                               : vertical_sun_slab(vec2(tau_below, tau_above), up, sun, -dir);
        vec3 L_diffuse = diffuse_inscatter(L, alt, tau_above, tau_below, sun_slab, mu_s, T_atm, coverage, E_sun, ground_sun,
                                           ground_sky, ground_albedo, -dot(dir, up), above);
        C += T * absorbed * (L_sun + L_diffuse);
        depth_acc += t * T * absorbed;
        if (T * absorbed > strongest) { strongest = T * absorbed; cloud_layer = li; }
        T *= 1.0 - absorbed;
      }
    }
  }
  float opacity = 1.0 - T;
  if (opacity > 1e-4) depth = depth_acc / opacity;
  if (cloud_layer >= 0) depth_layer = cloud_layer;
  // aerial perspective between the camera and the clouds, at their transmittance-weighted
  // depth: evaluated with the sample, so temporal reuse reuses it too
  if (opacity > 0.0) {
    vec3 ap_in, ap_T;
    aerial_perspective(dir, max(depth, 0.0), ap_in, ap_T);
    C = C * ap_T + opacity * E_sun * ap_in;
  }

  return RaySample(C, T, depth, depth_layer);
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  ivec2 q = cell * temporal.fresh_stride + temporal.fresh_offset;  // the cloud pixel this invocation marches
  if (any(greaterThanEqual(q, temporal.cloud_buffer_size))) return;
  // the ray through the pixel centre (footprint sample 0), or (footprint jitter, sample
  // n >= 1 of a still camera's accumulation; footprint_sample_index()) through the n-th
  // point of the pixel's sequence: offsets fract(r_q + n alpha) - 1/2 in cloud pixels,
  // alpha the R2 sequence's (Roberts 2018: 1/g, 1/g^2, g^3 = g + 1), r_q a per-pixel
  // rotation so that neighbours do not move in step. Likewise where the marched column
  // depths' nodes lie within their steps (marched_column_depths, column_quadrature.glsl):
  // at the steps' ends for the centre sample (offset 1/2), then shifted by the n-th point of
  // a per-pixel rotated golden-ratio sequence, so that a still camera's history integrates
  // each column with many times the steps (the sequence's first n points fill [0, 1) evenly).
  vec2 sub_pixel = vec2(0.0);
  float column_offset = 0.5;
  float sample_weight = CENTRE_SAMPLE_WEIGHT;
  if (frame.footprint_jitter != 0 && temporal.footprint_sample > 0) {
    sample_weight = 1.0;
    float n = float(temporal.footprint_sample);
    vec2 r_q = vec2(hash12(uvec2(q) * 3u + 11u), hash12(uvec2(q) * 5u + 17u));
    sub_pixel = fract(r_q + n * vec2(0.7548776662, 0.5698402910)) - 0.5;
    column_offset = fract(hash12(uvec2(q) * 7u + 23u) + n * 0.6180339887);
  }
  vec3 dir = view_ray(cloud_pixel_ndc(vec2(q) + sub_pixel));
  RaySample own = march_ray(q, dir, column_offset);
  vec3 C = own.C;
  float T = own.T, depth = own.depth;
  int layer = own.layer;
  float share_shift = 0.0;  // the clouds' shift of the ground share (see below)

  // A footprint the horizon crosses is sampled on both sides (stratified by area): the
  // clouds in front of the ground and those in front of the sky differ (a layer just above
  // the horizon hides the sky part only), and the composite needs the share of each in the
  // transmitted background. That ground share is f T_g / T; stored is its shift from the
  // area fraction f by the clouds, 0 where they are alike (or absent: a cleared buffer).
  // The other side's ray keeps this ray's azimuth and mirrors its relative position within
  // its side's elevation range (at least 5 % into it).
  vec2 ndc_centre = cloud_pixel_ndc(vec2(q));
  HorizonFootprint fp = footprint_at_horizon(ndc_centre, float(temporal.cloud_divisor) * vec2(1.0, -1.0) / frame.image_size_px,
                                             view_ray(ndc_centre));
  if (crosses_horizon(fp) && abs(dir.z) < 0.999) {
    float e = asin(clamp(dir.z, -1.0, 1.0));
    bool below = e < fp.e_h;
    float s = below ? (fp.e_h - e) / max(fp.e_h - fp.e_lo, 1e-9) : (e - fp.e_h) / max(fp.e_hi - fp.e_h, 1e-9);
    s = clamp(s, 0.05, 1.0);
    float e_other = below ? fp.e_h + s * (fp.e_hi - fp.e_h) : fp.e_h - s * (fp.e_h - fp.e_lo);
    RaySample other = march_ray(q, at_elevation(dir, e_other), column_offset);
    RaySample g = below ? own : other, k = below ? other : own;  // ground side, sky side
    float f = fp.f_ground;
    C = f * g.C + (1.0 - f) * k.C;
    T = f * g.T + (1.0 - f) * k.T;
    // 0/0 (opaque both ways): no shift
    share_shift = T > 1e-6 ? f * g.T / T - f : 0.0;
    // depth and layer: the opacity-weighted depth of both, the layer of the more opaque side
    float wg = f * (1.0 - g.T), wk = (1.0 - f) * (1.0 - k.T);
    if (wg + wk > 1e-4) depth = (wg * g.depth + wk * k.depth) / (wg + wk);
    layer = wg >= wk ? (g.layer >= 0 ? g.layer : k.layer) : (k.layer >= 0 ? k.layer : g.layer);
  }

  if (frame.count_density_evaluations != 0) atomicAdd(counters.density_evals, g_density_evals);
  imageStore(fresh_radiance, cell, vec4(C, T));
  imageStore(fresh_depth, cell, vec4(depth, share_shift, float(layer), sample_weight));
  count_if_loops_capped();
}
