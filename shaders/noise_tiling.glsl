// The stochastic tiling of the base-shape and detail noise on the GPU (weather/noise_tiling.h:
// four staggered cubic lattices of cells one period wide, each cell reading the noise at
// its own hashed offset, blended with variance-preserving weights; the same integer hashes,
// so the CPU reference reads the same field). Positions s are in periods relative to the
// camera's cell: s = field point / P + frac(camera / P) (CloudLayerGpu.*_noise_offset), and a
// cell's absolute index is the camera's cell (CloudLayerGpu.*_noise_cell) + floor(s - k/4).
// Needs common.glsl (hash32) and frame_uniforms.glsl.

const int TILING_LATTICES = 4;               // weather::kTilingLattices
const float TILING_FACE_BAND = 3.0 / 32.0;   // weather::kTilingFaceBand

// o_k of a lattice's cell c (absolute index), periods in [0, 1)^3 (weather::tiling_offset):
// one hash of the cell, 10 bits per axis
vec3 tiling_offset(ivec3 c, uint lattice_seed) {
  uint h = hash32(uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u ^ uint(c.z) * 0xcb1ab31fu ^ lattice_seed);
  return vec3(uvec3(h, h >> 10, h >> 20) & 1023u) * (1.0 / 1024.0);
}

// w_k at x = s - k/4 (weather::tiling_weight)
float tiling_weight(vec3 x) {
  vec3 t = (fract(x) - TILING_FACE_BAND) / (1.0 - 2.0 * TILING_FACE_BAND);
  vec3 b = max(4.0 * t * (1.0 - t), 0.0);
  b *= b;
  return b.x * b.y * b.z;
}

// The tiled value of a noise volume at s (weather::tiled_noise) for the camera's cell, the
// four lattice seeds and the volume's mean. All four lattices are read (a lattice without
// weight at s adds 0): on llvmpipe, skipping them per lane saves nothing (measured).
float tiled_noise(sampler3D volume, vec3 s, ivec3 camera_cell, uvec4 seeds, float mean) {
  float num = 0.0, w2 = 0.0;
  for (int k = 0; k < TILING_LATTICES; ++k) {
    vec3 sk = s - 0.25 * float(k);
    float w = tiling_weight(sk);
    vec3 o = tiling_offset(camera_cell + ivec3(floor(sk)), seeds[k]);
    num += w * (textureLod(volume, s + o, 0.0).r - mean);
    w2 += w * w;
  }
  return saturate(mean + num * inversesqrt(w2));
}

// The per-axis factor of tiling_weight at u = frac(x).
float tiling_axis_bump(float u) {
  float t = (u - TILING_FACE_BAND) / (1.0 - 2.0 * TILING_FACE_BAND);
  float b = max(4.0 * t * (1.0 - t), 0.0);
  return b * b;
}

// The range [min, max] of tiling_weight over the box [x_lo, x_hi] (weather::tiling_weight_range).
vec2 tiling_weight_range(vec3 x_lo, vec3 x_hi) {
  vec2 w = vec2(1.0);
  for (int a = 0; a < 3; ++a) {
    float u0 = fract(x_lo[a]), u1 = u0 + (x_hi[a] - x_lo[a]);
    float b0 = tiling_axis_bump(u0), b1 = tiling_axis_bump(u1 >= 1.0 ? u1 - 1.0 : u1);
    bool centre = (u0 <= 0.5 && u1 >= 0.5) || u1 >= 1.5 || x_hi[a] - x_lo[a] >= 1.0;
    w.x *= u1 >= 1.0 ? 0.0 : min(b0, b1);
    w.y *= centre ? 1.0 : max(b0, b1);
  }
  return w;
}

// An upper bound of the tiled base noise of layer L over the box [s_lo, s_hi]
// (weather::tiled_max_over and weather::tiling_bound, the same rules; base_noise_max_over
// reads the max pyramid).
float tiled_base_noise_max_over(CloudLayerGpu L, vec3 s_lo, vec3 s_hi) {
  float mu = frame.base_noise_mean;
  float largest = 0.0, above2 = 0.0, num = 0.0, den2 = 0.0;
  for (int k = 0; k < TILING_LATTICES; ++k) {
    vec3 x_lo = s_lo - 0.25 * float(k), x_hi = s_hi - 0.25 * float(k);
    vec3 c_min = floor(x_lo + TILING_FACE_BAND);
    vec3 c_max = ceil(x_hi - TILING_FACE_BAND) - 1.0;
    if (any(greaterThan(c_min, c_max))) continue;              // no weight in the box
    if (any(notEqual(c_min, c_max))) return 1.0;               // several cells, several offsets
    vec3 o = tiling_offset(L.base_noise_cell + ivec3(c_min), L.base_tiling_seeds[k]);
    float m = base_noise_max_over(s_lo + o, s_hi + o);
    vec2 w = tiling_weight_range(x_lo, x_hi);
    float a = max(m - mu, 0.0);
    largest = max(largest, m);
    above2 += a * a;
    num += w.y * a;
    den2 += w.x * w.x;
  }
  if (largest <= mu) return largest;
  float gain = den2 > 0.0 ? min(sqrt(above2), num * inversesqrt(den2)) : sqrt(above2);
  return min(1.0, mu + gain);
}
