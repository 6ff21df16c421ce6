#version 450 core
// Temporal resolve of the cloud buffer (temporal_uniforms.glsl). Every cloud pixel gets:
//  - fresh this frame: its new sample; while the camera is still, blended with its
//    history with weight max(w / (n + w), blend.x), w the sample's weight and n the total
//    of the earlier ones' (a jittered footprint sample weighs 1, the pixel centre
//    CENTRE_SAMPLE_WEIGHT of cloud_march.comp; averages the step and footprint jitter out);
//  - not fresh: its history, reprojected with the real camera motion, the wind of the
//    cloud layer it shows and its cloud depth (two fixed-point iterations: the depth
//    stored where the ray pointed last frame), limited to the range of the fresh samples
//    around it when the view moved (Karis 2014 neighbourhood clamp: no ghosts where
//    something else is uncovered);
//  - no usable history (first frame, a teleport, off-screen last frame): the fresh
//    samples around it, interpolated bilinearly.
// Koblížek 2020 §3.2: 1/16-pixel reprojection in 4 x 4 blocks; Schneider 2015.
#include "common.glsl"
#include "frame_uniforms.glsl"
#include "temporal_uniforms.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_FRESH_RADIANCE) uniform sampler2D fresh_radiance;
layout(binding = TEX_FRESH_DEPTH) uniform sampler2D fresh_depth;
layout(binding = TEX_HISTORY_RADIANCE) uniform sampler2D history_radiance;  // previous resolved buffer, linear filter
layout(binding = TEX_HISTORY_DEPTH) uniform sampler2D history_depth;
layout(rgba32f, binding = IMG_CLOUD_RADIANCE_OUT) uniform writeonly image2D next_radiance;
layout(rgba32f, binding = IMG_CLOUD_DEPTH_OUT) uniform writeonly image2D next_depth;

// Cloud-buffer texture coordinates in the previous frame of the current-local point p
// seen through the field (or ground) transform m; false when behind the previous camera.
bool reproject(vec3 p, int m, out vec2 uv) {
  vec3 pp = (temporal.reproject[m] * vec4(p, 1.0)).xyz;
  float z = dot(pp, temporal.prev_forward);
  uv = vec2(-1.0);
  if (z <= 1e-3 * length(pp)) return false;
  vec2 ndc = vec2((dot(pp, temporal.prev_right) / z - temporal.prev_center_tan_x) / temporal.prev_tan_half_fov_x,
                  (dot(pp, temporal.prev_up) / z - temporal.prev_center_tan_y) / temporal.prev_tan_half_fov_y);
  vec2 full = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * frame.image_size_px;  // frame pixels, row 0 at the top
  uv = full / float(temporal.cloud_divisor) / vec2(temporal.cloud_buffer_size);
  return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// History at uv with a Catmull-Rom filter (4x4 texels): a moving camera resamples the
// history every frame, and a bilinear filter would blur it a little more each time.
// Limited to the range of the 2x2 nearest texels (no ringing, no negative values).
vec4 history_cubic(vec2 uv) {
  vec2 pos = uv * vec2(temporal.cloud_buffer_size) - 0.5;
  vec2 base = floor(pos);
  vec2 f = pos - base;
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 wx[4] = vec2[4](w0, w1, w2, w3);
  ivec2 b = ivec2(base) - 1;
  ivec2 hi_px = temporal.cloud_buffer_size - 1;
  vec4 sum = vec4(0.0), lo = vec4(1e30), hi = vec4(-1e30);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      vec4 v = texelFetch(history_radiance, clamp(b + ivec2(i, j), ivec2(0), hi_px), 0);
      sum += wx[i].x * wx[j].y * v;
      if ((i == 1 || i == 2) && (j == 1 || j == 2)) { lo = min(lo, v); hi = max(hi, v); }
    }
  return clamp(sum, lo, hi);
}

int transform_of(float layer) { return layer >= 0.0 ? int(layer) : MAX_LAYERS; }  // MAX_LAYERS: the ground

ivec2 texel_of(vec2 uv) { return clamp(ivec2(uv * vec2(temporal.cloud_buffer_size)), ivec2(0), temporal.cloud_buffer_size - 1); }

// Change detection thresholds: cloud transmittance, and relative radiance (the jitter
// noise of one sample is well below both away from cloud edges).
const float CHANGE_T = 0.15;
const float CHANGE_REL = 0.15;
const int CHANGE_MIN_NEIGHBOURS = 3;  // of 4: one alone is jitter at a cloud edge

bool finite4(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }

// The fresh samples cs[0..3] around a cloud pixel: their bilinear interpolation with
// weights ws, their range (lo, hi) and the index of the nearest (largest weight, first).
void fresh_neighbourhood(ivec2 cs[4], float ws[4], out vec4 fresh[4], out vec4 up, out vec4 lo, out vec4 hi,
                         out int nearest) {
  up = vec4(0.0);
  lo = vec4(1e30);
  hi = vec4(-1e30);
  nearest = 0;
  for (int i = 0; i < 4; ++i) {
    fresh[i] = texelFetch(fresh_radiance, cs[i], 0);
    up += ws[i] * fresh[i];
    lo = min(lo, fresh[i]);
    hi = max(hi, fresh[i]);
    if (ws[i] > ws[nearest]) nearest = i;
  }
}

// The ground-share shift (cloud_march.comp) of the fresh samples cs around a cloud pixel,
// interpolated with weights ws (as their radiance and transmittance where they stand in).
float fresh_share_shift(ivec2 cs[4], float ws[4]) {
  float shift = 0.0;
  for (int i = 0; i < 4; ++i) shift += ws[i] * texelFetch(fresh_depth, cs[i], 0).y;
  return shift;
}

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(q, temporal.cloud_buffer_size))) return;
  int s = temporal.fresh_stride;
  ivec2 rel = q - temporal.fresh_offset;
  ivec2 fsize = max((temporal.cloud_buffer_size - temporal.fresh_offset + s - 1) / s, ivec2(1));  // fresh samples per axis
  bool is_fresh = all(greaterThanEqual(rel, ivec2(0))) && rel.x % s == 0 && rel.y % s == 0;

  // The fresh samples around q: bilinear weights; their interpolation and range are read
  // only where they are used (no or stale history, the clamp of a moving view), the
  // nearest one's depth only where there is no history (5 texel reads a pixel saved where
  // the history is kept as it is).
  vec2 cf = vec2(rel) / float(s);
  ivec2 c0 = clamp(ivec2(floor(cf)), ivec2(0), fsize - 1);
  ivec2 c1 = min(c0 + 1, fsize - 1);
  vec2 f = clamp(cf - vec2(c0), 0.0, 1.0);
  ivec2 cs[4] = ivec2[4](c0, ivec2(c1.x, c0.y), ivec2(c0.x, c1.y), c1);
  float ws[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  vec4 fresh_own_a = is_fresh ? texelFetch(fresh_radiance, rel / s, 0) : vec4(0.0);
  vec4 fresh_own_b = is_fresh ? texelFetch(fresh_depth, rel / s, 0) : vec4(0.0);

  // The neighbourhood is needed without history (the interpolated fresh samples stand in)
  // and for a moving view (change detection, clamp); a still view with history skips it.
  bool moving = temporal.camera_still == 0;
  vec4 fresh_at[4], up_a, lo, hi;
  int nearest;

  vec4 out_a = vec4(0.0), out_b = vec4(0.0);
  bool from_history = false;
  if (temporal.history_valid != 0) {
    vec3 dir = view_ray(cloud_pixel_ndc(vec2(q)));
    // clouds: the point at the depth stored where this ray pointed last frame, twice (the
    // second read is skipped where it would read the same texel again)
    vec4 hb = texelFetch(history_depth, q, 0);
    vec2 uv;
    bool ok = reproject(hb.x * dir, transform_of(hb.z), uv);
    if (ok && texel_of(uv) != q) {
      hb = texelFetch(history_depth, texel_of(uv), 0);
      ok = reproject(hb.x * dir, transform_of(hb.z), uv);
    }
    vec2 motion = uv * vec2(temporal.cloud_buffer_size) - (vec2(q) + 0.5);  // cloud pixels
    float moved = length(motion);
    // A history that did not move (a still camera, no wind) is read as it is: no filter.
    vec4 ha = moved < 1e-3 ? texelFetch(history_radiance, q, 0) : history_cubic(uv);
    ok = ok && finite4(ha) && finite4(hb);
    if (ok) {
      from_history = true;
      float n = hb.w;
      // Has the scene changed around q? Compare the fresh samples with the history at
      // their positions (moved by q's motion); a cloud flown into, or one uncovered, shows
      // there even when q's own reprojection looks still. Only for a moving camera: a
      // still camera sees the same scene (its drift is in the reprojection), differences
      // there are the jitter noise that accumulation removes.
      int n_changed = 0;
      if (moving || (temporal.neighbourhood_clamp != 0 && moved > 0.5))
        fresh_neighbourhood(cs, ws, fresh_at, up_a, lo, hi, nearest);
      for (int i = 0; i < 4 && moving; ++i) {
        vec2 pos_i = vec2(cs[i] * s + temporal.fresh_offset) + 0.5 + motion;
        vec4 h_i = textureLod(history_radiance, pos_i / vec2(temporal.cloud_buffer_size), 0.0);
        float y_f = dot(fresh_at[i].rgb, vec3(1.0)), y_h = dot(h_i.rgb, vec3(1.0));
        n_changed += (abs(fresh_at[i].a - h_i.a) > CHANGE_T || abs(y_f - y_h) > CHANGE_REL * (y_f + y_h) + 1e-9) ? 1 : 0;
      }
      bool changed = moving && n_changed >= CHANGE_MIN_NEIGHBOURS;
      if (temporal.neighbourhood_clamp != 0 && changed) ha = up_a;  // stale: the fresh samples around it
      else if (temporal.neighbourhood_clamp != 0 && moved > 0.5) ha = clamp(ha, lo, hi);
      if (is_fresh) {
        // a moved or changed history is resampled or stale: a fresh sample replaces it; a
        // still one is averaged with it
        // (n, fresh_own_b.w: the sample weights, cloud_march.comp's CENTRE_SAMPLE_WEIGHT)
        float n_fresh = fresh_own_b.w;
        float w = (moving || moved > 0.1 || changed) ? 1.0 : max(n_fresh / (n + n_fresh), temporal.history_blend_min);
        out_a = mix(ha, fresh_own_a, w);
        out_b = vec4(mix(hb.x, fresh_own_b.x, w), mix(hb.y, fresh_own_b.y, w), fresh_own_b.z, min(n + n_fresh, 255.0));
      } else {
        out_a = ha;
        out_b = vec4(hb.x, changed && temporal.neighbourhood_clamp != 0 ? fresh_share_shift(cs, ws) : hb.y, hb.z, n);
      }
    }
  }
  if (!from_history) {
    if (is_fresh) {
      out_a = fresh_own_a;
      out_b = fresh_own_b;
    } else {
      // the fresh samples around q, interpolated; the depth of the nearest one
      fresh_neighbourhood(cs, ws, fresh_at, out_a, lo, hi, nearest);
      vec4 near_b = texelFetch(fresh_depth, cs[nearest], 0);
      out_b = vec4(near_b.x, fresh_share_shift(cs, ws), near_b.z, 0.0);
    }
  }
  imageStore(next_radiance, q, out_a);
  imageStore(next_depth, q, out_b);
}
