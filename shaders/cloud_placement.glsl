// The cloud placement of weather/cloud_placement.h on the GPU: the same hashes, cubes and
// discs, evaluated in float relative to a centre point C on the shell (camera-relative, no
// cancellation): per level, C's cube index (integers) and its offset inside that cube are
// given, so cube indices near C come out exact and every length is small. Source of truth
// for the process: weather/cloud_placement.cpp (this file must agree with it bit for bit
// in the integer hashes; tests/gpu_cloud_placement_test.cpp compares the dome tops).

// weather/noise_hash.h's hash_cell (hash32, hash_to_unit: common.glsl)
uint placement_hash_cell(ivec3 c, uint seed) {
  uint h = hash32((seed * 0x9e3779b1u + 0x7f4a7c15u) ^ uint(c.x));
  h = hash32(h ^ uint(c.y));
  return hash32(h ^ uint(c.z));
}

const int PLACEMENT_MAX_LEVELS = 8;

struct PlacementFrame {
  vec3 centre;  // C, field frame (m), |C| = R: only its direction and dot products are used
  float shell_radius_m;
  int levels;
  float smallest_cell_m;
  float rho_min, rho_max;
  ivec4 centre_cell[PLACEMENT_MAX_LEVELS];  // xyz: floor(C / s_k)
  vec4 centre_offset[PLACEMENT_MAX_LEVELS];  // xyz: C - s_k floor(C / s_k), in [0, s_k)
  vec4 acceptance;                           // p_k for the levels 0..3 where one coverage holds
                                             // (tests; the rings read the map at each centre)
  vec4 acceptance_hi;                        // ... 4..7
  uint level_seed[PLACEMENT_MAX_LEVELS];
};

// |C + d| - R without cancellation: (2 C.d + |d|^2) / (|C + d| + R).
float placement_radial_offset(PlacementFrame pf, vec3 d) {
  float R = pf.shell_radius_m;
  float num = 2.0 * dot(pf.centre, d) + dot(d, d);
  return num / (length(pf.centre + d) + R);
}

// The projection of C + d onto the shell, relative to C: d k + C (k - 1), k = R / |C + d|,
// with k - 1 = -(|C + d| - R) / |C + d|.
vec3 placement_project(PlacementFrame pf, vec3 d) {
  float dr = placement_radial_offset(pf, d);
  float len = pf.shell_radius_m + dr;
  return d * (pf.shell_radius_m / len) - pf.centre * (dr / len);
}

// The acceptance probability p_k of a level-k candidate whose cloud centre is C + centre
// (on the shell): defined by the including shader (the weather map's coverage there, or a
// frame's fixed per-level values).
float placement_acceptance(PlacementFrame pf, int level, vec3 centre);

// The unit-aspect dome top of the clouds of levels [first_level, end_level) at the shell point
// C + x (CloudPlacement::dome_top): max over the accepted candidates near x of
// (r^2 - d^2) / r (m), never below -floor_m.
float placement_dome_top(PlacementFrame pf, vec3 x, int first_level, int end_level, float floor_m) {
  float top = -floor_m;
  for (int k = first_level; k < min(end_level, pf.levels); ++k) {
    float s = pf.smallest_cell_m * exp2(float(k));
    vec3 local = pf.centre_offset[k].xyz + x;
    ivec3 rel = ivec3(floor(local / s));
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          ivec3 r = rel + ivec3(dx, dy, dz);
          uint h = placement_hash_cell(pf.centre_cell[k].xyz + r, pf.level_seed[k]);
          vec3 u = vec3(hash_to_unit(hash32(h ^ 1u)), hash_to_unit(hash32(h ^ 2u)),
                        hash_to_unit(hash32(h ^ 3u)));
          vec3 q = (vec3(r) + u) * s - pf.centre_offset[k].xyz;
          if (!(abs(placement_radial_offset(pf, q)) < 0.5 * s)) continue;
          vec3 c = placement_project(pf, q);
          float radius = (pf.rho_min + (pf.rho_max - pf.rho_min) * hash_to_unit(hash32(h ^ 5u))) * s;
          vec3 d = x - c;
          float dome = (radius * radius - dot(d, d)) / radius;
          if (!(dome > top)) continue;
          if (!(hash_to_unit(hash32(h ^ 4u)) < placement_acceptance(pf, k, c))) continue;
          top = dome;
        }
  }
  return top;
}
