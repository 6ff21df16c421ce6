// Shared constants and numerically careful helpers.
const float PI = 3.14159265358979;
const float INV_4PI = 0.0795774715459477;

float saturate(float x) { return clamp(x, 0.0, 1.0); }
float remap(float x, float a, float b, float c, float d) { return c + (x - a) * (d - c) / (b - a); }

// 1 - exp(-x) without cancellation for small x (GLSL has no expm1): the series is used
// below x = 1e-3, where it is accurate to float precision. x >= 0 (optical depth).
float one_minus_exp_neg(float x) {
  return x < 1e-3 ? x * (1.0 - 0.5 * x + x * x / 6.0) : 1.0 - exp(-x);
}

// Ray / sphere-shell intersection in the cancellation-free form of Haines et al. 2019
// (Ray Tracing Gems ch. 7) and geodesy/shell_intersection.h. The ray starts
// at altitude h above a sphere of radius R with mu = cos(angle to local up); the shell is
// at altitude H. Returns (t_near, t_far); t < 0 marks "no hit" for that root. A start
// inside the shell gives (-1, t_exit).
vec2 intersect_shell(float R, float h, float H, float mu) {
  float c = (h - H) * (2.0 * R + h + H);
  float b = -(R + h) * mu;
  float disc = b * b - c;
  if (disc < 0.0) return vec2(-1.0);
  float q = b + (b >= 0.0 ? sqrt(disc) : -sqrt(disc));
  float t0 = q == 0.0 ? 0.0 : c / q;
  float t1 = q;
  if (t0 > t1) { float t = t0; t0 = t1; t1 = t; }
  if (t1 < 0.0) return vec2(-1.0);
  return vec2(t0, t1);
}

// Altitude above the shell sphere of the point p (local frame, m), written without the
// cancellation of |p - centre| - R: with C = R + h,
//   r^2 - R^2 = |p|^2 + 2 C p.z + h (2R + h),   alt = (r^2 - R^2) / (r + R).
float altitude_of(vec3 p, float R, float h) {
  float C = R + h;
  float num = dot(p, p) + 2.0 * C * p.z + h * (2.0 * R + h);
  float r = sqrt(max(C * C + 2.0 * C * p.z + dot(p, p), 0.0));
  return num / (r + R);
}

// Unit "up" (away from the shell centre) at point p.
vec3 up_at(vec3 p, float R, float h) { return normalize(p + vec3(0.0, 0.0, R + h)); }

// The "lowbias32" integer finaliser, the same as weather/noise_hash.h's hash32 (wraps mod
// 2^32 like the C++), and a uniform float in [0, 1) from its top 24 bits (hash_to_unit).
uint hash32(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}
float hash_to_unit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

// Small integer hash (PCG-style) -> [0, 1).
float hash12(uvec2 v) { return hash_to_unit(hash32(v.x * 1664525u + v.y * 1013904223u)); }
