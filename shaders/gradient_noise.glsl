// Perlin "improved" gradient noise (Perlin 2002), non-periodic, the same lattice hashes and
// gradients as weather/gradient_noise.cpp's perlin_noise (period 0), evaluated at a lattice
// point given as an integer cell plus a fractional offset: far from the origin (the field
// frame's coordinates are millions of metres) float keeps the offset exact where the
// absolute coordinate would lose it. Needs common.glsl (hash32).

// The 12 cube-edge gradients, indexed by k = hash % 12: k / 4 picks the pair of axes
// ((x, y), (x, z), (y, z)), bit 0 negates the first, bit 1 the second:
// k = 0: x + y, 1: -x + y, 2: x - y, 3: -x - y, 4..7 the same with (x, z), 8..11 with (y, z).
// Written with selects, not a switch: llvmpipe runs every case of a switch for every lane
// (docs/PERFORMANCE.md), and the sums are the same float operations either way.
float gradient_dot(uint h, vec3 d) {
  uint k = h % 12u;
  float a = k < 8u ? d.x : d.y;
  float b = k < 4u ? d.y : d.z;
  return ((k & 1u) != 0u ? -a : a) + ((k & 2u) != 0u ? -b : b);
}

vec3 perlin_fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// The noise at lattice coordinates cell + offset (offset any float vector; its integer part
// moves the cell). seed: the noise's seed.
float perlin_noise_at(ivec3 cell, vec3 offset, uint seed) {
  vec3 fl = floor(offset);
  ivec3 c = cell + ivec3(fl);
  vec3 d = offset - fl;
  uint hx0 = hash32((seed * 0x9e3779b1u + 0x7f4a7c15u) ^ uint(c.x));
  uint hx1 = hash32((seed * 0x9e3779b1u + 0x7f4a7c15u) ^ uint(c.x + 1));
  uint h00 = hash32(hx0 ^ uint(c.y)), h10 = hash32(hx1 ^ uint(c.y));
  uint h01 = hash32(hx0 ^ uint(c.y + 1)), h11 = hash32(hx1 ^ uint(c.y + 1));
  float n000 = gradient_dot(hash32(h00 ^ uint(c.z)), d);
  float n100 = gradient_dot(hash32(h10 ^ uint(c.z)), d - vec3(1, 0, 0));
  float n010 = gradient_dot(hash32(h01 ^ uint(c.z)), d - vec3(0, 1, 0));
  float n110 = gradient_dot(hash32(h11 ^ uint(c.z)), d - vec3(1, 1, 0));
  float n001 = gradient_dot(hash32(h00 ^ uint(c.z + 1)), d - vec3(0, 0, 1));
  float n101 = gradient_dot(hash32(h10 ^ uint(c.z + 1)), d - vec3(1, 0, 1));
  float n011 = gradient_dot(hash32(h01 ^ uint(c.z + 1)), d - vec3(0, 1, 1));
  float n111 = gradient_dot(hash32(h11 ^ uint(c.z + 1)), d - vec3(1, 1, 1));
  vec3 u = perlin_fade(d);
  return mix(mix(mix(n000, n100, u.x), mix(n010, n110, u.x), u.y), mix(mix(n001, n101, u.x), mix(n011, n111, u.x), u.y),
             u.z);
}
