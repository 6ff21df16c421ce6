// The parts of a view ray inside the cloud layers (shell intervals), and the march
// coordinate that spaces primary steps. Needs common.glsl and frame_uniforms.glsl.

const int MAX_INTERVALS = 8;  // two per layer (a layer shell can be entered twice)

struct Interval { float t0; float t1; int layer; };

// March coordinate u(t) = ln(1 + t / t_ref) (or t itself when t_ref = 0) and its inverse:
// steps uniform in u grow in proportion to distance, like the pixel footprint.
float march_coordinate(float t, float t_ref) { return t_ref > 0.0 ? log(1.0 + t / t_ref) : t; }
float march_distance(float u, float t_ref) { return t_ref > 0.0 ? t_ref * (exp(u) - 1.0) : u; }

// The part of the ray inside layer li, as up to two intervals [entry, exit] clipped to
// [t_start, t_limit]: inside the top sphere and outside the base sphere.
int layer_intervals(int li, float mu, float t_start, float t_limit, out Interval a, out Interval b) {
  float R = frame.shell_radius_m, h = frame.camera_altitude_m;
  vec2 top = intersect_shell(R, h, frame.layers[li].top_m, mu);
  vec2 base = intersect_shell(R, h, frame.layers[li].base_m, mu);
  int n = 0;
  if (top.y < 0.0) return 0;
  float A0 = max(top.x, t_start), A1 = min(top.y, t_limit);
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

// All layer intervals of the ray with zenith cosine mu between t_start and t_limit, sorted
// by entry distance; total_len is their summed length in march coordinates.
int ray_intervals(float mu, float t_start, float t_limit, float t_ref, out Interval iv[MAX_INTERVALS],
                  out float total_len) {
  int n_iv = 0;
  total_len = 0.0;
  for (int li = 0; li < frame.layer_count; ++li) {
    Interval a, b;
    int n = layer_intervals(li, mu, t_start, t_limit, a, b);
    if (n >= 1) total_len += march_coordinate(a.t1, t_ref) - march_coordinate(a.t0, t_ref);
    if (n == 2) total_len += march_coordinate(b.t1, t_ref) - march_coordinate(b.t0, t_ref);
    // coverage 0: no cloud anywhere (a clear layer, or none within reach of this frame,
    // renderer/coverage_cull.h): nothing to march; its length stays in the step budget, so
    // the other layers are marched with exactly the steps they get without the cull
    if (frame.layers[li].coverage <= 0.0) continue;
    if (n >= 1) iv[n_iv++] = a;
    if (n == 2) iv[n_iv++] = b;
  }
  for (int i = 1; i < n_iv; ++i) {  // insertion sort
    Interval x = iv[i];
    int j = i - 1;
    while (j >= 0 && iv[j].t0 > x.t0) { iv[j + 1] = iv[j]; --j; }
    iv[j + 1] = x;
  }
  return n_iv;
}
