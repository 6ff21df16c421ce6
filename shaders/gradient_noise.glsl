// Perlin "improved" gradient noise (Perlin 2002), non-periodic, the same lattice hashes and
// gradients as weather/gradient_noise.cpp's perlin_noise (period 0), evaluated at a lattice
// point given as an integer cell plus a fractional offset: far from the origin (the field
// frame's coordinates are millions of metres) float keeps the offset exact where the
// absolute coordinate would lose it. Needs common.glsl (hash32).

// The 12 cube-edge gradients, indexed by hash % 12.
float gradient_dot(uint h, vec3 d) {
  switch (h % 12u) {
    case 0u: return d.x + d.y;   case 1u: return -d.x + d.y;  case 2u: return d.x - d.y;   case 3u: return -d.x - d.y;
    case 4u: return d.x + d.z;   case 5u: return -d.x + d.z;  case 6u: return d.x - d.z;   case 7u: return -d.x - d.z;
    case 8u: return d.y + d.z;   case 9u: return -d.y + d.z;  case 10u: return d.y - d.z;  default: return -d.y - d.z;
  }
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
