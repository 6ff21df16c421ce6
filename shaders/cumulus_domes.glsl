// Reading a cumulus layer's dome top on the GPU (weather::DomeTopSampler, weather/dome_rings.h,
// the same in double): the finest dome ring holding the point (manual bilinear over
// texelFetch, so the weights are exact as on the CPU), the max of its top and the sub-grid
// top of the finer levels (weather::DomeSubgrid), blended into the next ring's reading over
// the ring's outer eighth; beyond the last ring every level is sub-grid. Field frame: ECEF
// axes turned with the layer's wind, metres, relative to the rings' anchor A on the dome
// shell (float-safe: every length is tens of km at most).
// Needs common.glsl and gradient_noise.glsl.

const int DOME_RINGS = 4;             // = weather::kDomeMaxRings
const int DOME_LEVELS = 4;            // = weather::kDomeLevels
const int DOME_SUBGRID_OCTAVES = 8;   // = 2 DOME_LEVELS
const int DOME_QUANTILES = 64;        // = weather::kDomeSubgridQuantiles

struct DomeLayerGpu {
  vec4 plane_e, plane_n, plane_c;     // xyz: the anchor plane's axes (field frame); plane_c.w: R_d (m)
  vec4 ring[DOME_RINGS];              // xy: ring centre on the plane (m), z: texel (m), w: first level
  ivec4 info;                         // x: rings, y: texels a side, z: first slice, w: levels
  vec4 params;                        // x: top floor (m), y: sub-grid mean radius (m), z: max coverage
  vec4 shape;                         // x: top scale L (m), y: cauliflower (m), z: edge (m), w: base ramp (m)
  vec4 camera_q;                      // xyz: the camera's field position minus the anchor (m)
  vec4 oct_rot[DOME_SUBGRID_OCTAVES * 3];  // rows of each octave's rotation; row 0 .w: weight
  ivec4 oct_cell[DOME_SUBGRID_OCTAVES];    // xyz: floor(rot A / lambda); w: seed (bits)
  vec4 oct_frac[DOME_SUBGRID_OCTAVES];     // xyz: rot A / lambda - cell; w: 1 / lambda (1/m)
  float quantile[(DOME_LEVELS + 1) * (DOME_QUANTILES + 1)];  // row l: n over l levels
  float rms[DOME_LEVELS + 1];
};

layout(std430, binding = SSBO_DOME_LAYERS) readonly buffer DomeLayers { DomeLayerGpu dome_layers[]; };
layout(binding = TEX_DOME_RINGS) uniform sampler2DArray dome_rings;

// The point of the dome shell below q (q: a point relative to the anchor, field frame),
// relative to the anchor: q k + A (k - 1), k = R_d / |A + q|, without cancellation.
vec3 dome_shell_point(int slot, vec3 q) {
  float R = dome_layers[slot].plane_c.w;
  float num = 2.0 * R * dot(q, dome_layers[slot].plane_c.xyz) + dot(q, q);  // |A + q|^2 - R^2
  float len = sqrt(R * R + num);
  float dr = num / (len + R);  // |A + q| - R
  return q * (R / len) - dome_layers[slot].plane_c.xyz * (R * dr / len);
}

// Plane coordinates (m) of the shell point above or below q.
vec2 dome_plane_coords(int slot, vec3 q) {
  float R = dome_layers[slot].plane_c.w;
  return R * vec2(dot(q, dome_layers[slot].plane_e.xyz), dot(q, dome_layers[slot].plane_n.xyz)) / (R + dot(q, dome_layers[slot].plane_c.xyz));
}

// Sub-grid noise over the first `levels` levels at the shell point s (relative to A).
float dome_subgrid_noise(int slot, vec3 s, int levels) {
  float n = 0.0;
  for (int i = 0; i < 2 * min(levels, DOME_LEVELS); ++i) {
    vec3 r = vec3(dot(dome_layers[slot].oct_rot[3 * i].xyz, s), dot(dome_layers[slot].oct_rot[3 * i + 1].xyz, s), dot(dome_layers[slot].oct_rot[3 * i + 2].xyz, s));
    n += dome_layers[slot].oct_rot[3 * i].w * perlin_noise_at(dome_layers[slot].oct_cell[i].xyz, dome_layers[slot].oct_frac[i].xyz + r * dome_layers[slot].oct_frac[i].w, uint(dome_layers[slot].oct_cell[i].w));
  }
  return n;
}

float dome_subgrid_quantile(int slot, float p, int levels) {
  float x = clamp(p, 0.0, 1.0) * float(DOME_QUANTILES);
  int i = min(int(x), DOME_QUANTILES - 1);
  int row = levels * (DOME_QUANTILES + 1);
  return mix(dome_layers[slot].quantile[row + i], dome_layers[slot].quantile[row + i + 1], x - float(i));
}

// DomeSubgrid::top_m
float dome_subgrid_top(int slot, vec3 s, int levels, float covered) {
  float floor_m = dome_layers[slot].params.x;
  if (levels <= 0 || covered <= 0.0) return -floor_m;
  float t = dome_layers[slot].params.y * (dome_subgrid_noise(slot, s, levels) - dome_subgrid_quantile(slot, 1.0 - covered, levels)) / dome_layers[slot].rms[levels];
  return max(t, -floor_m);
}

// Ring k's bilinear (top, covered fraction) at plane coordinates uv.
vec2 dome_ring_bilinear(int slot, int k, vec2 uv) {
  float h = dome_layers[slot].ring[k].z;
  vec2 g = (uv - dome_layers[slot].ring[k].xy) / h + 0.5 * float(dome_layers[slot].info.y) - 0.5;  // texel units in the ring
  vec2 f = floor(g), w = g - f;
  ivec2 i = ivec2(f);
  int slice = dome_layers[slot].info.z + k;
  vec2 a = texelFetch(dome_rings, ivec3(i, slice), 0).rg, b = texelFetch(dome_rings, ivec3(i + ivec2(1, 0), slice), 0).rg;
  vec2 c = texelFetch(dome_rings, ivec3(i + ivec2(0, 1), slice), 0).rg, d = texelFetch(dome_rings, ivec3(i + ivec2(1, 1), slice), 0).rg;
  return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

// dome_ring_weight
float dome_ring_weight(int slot, int k, vec2 uv) {
  vec2 t = abs(uv - dome_layers[slot].ring[k].xy) / dome_layers[slot].ring[k].z;
  float inner = 0.5 * float(dome_layers[slot].info.y) - 1.5, fade = 0.0625 * float(dome_layers[slot].info.y);
  return clamp((inner - max(t.x, t.y)) / fade, 0.0, 1.0);
}

// The unit-aspect dome top (m) of dome layer `slot` above or below q (relative to the
// anchor, field frame); coverage_here: the layer's coverage there (for the sub-grid beyond
// the last ring).
float dome_top(int slot, vec3 q, float coverage_here) {
    vec2 uv = dome_plane_coords(slot, q);
  vec3 s = dome_shell_point(slot, q);
  float result = 0.0, remaining = 1.0;
  for (int k = 0; k < dome_layers[slot].info.x && remaining > 0.0; ++k) {
    float w = dome_ring_weight(slot, k, uv);
    if (w <= 0.0) continue;
    vec2 t = dome_ring_bilinear(slot, k, uv);
    float rep = max(t.x, dome_subgrid_top(slot, s, int(dome_layers[slot].ring[k].w), t.y));
    result += remaining * w * rep;
    remaining -= remaining * w;
  }
  if (remaining > 0.0) {
    // over every level the covered fraction is the coverage itself (up to the placement's max)
    result += remaining * dome_subgrid_top(slot, s, dome_layers[slot].info.w, min(coverage_here, dome_layers[slot].params.z));
  }
  return result;
}

// weather::dome_fraction: the cloud fraction at height h above the base of dome layer `slot`
// under the unit top `unit_top`, capped at the ceiling (m above the base), with the layer's
// base-shape noise minus its median.
float dome_fraction(int slot, float unit_top, float ceiling, float h, float shape_minus_median) {
  vec4 sh = dome_layers[slot].shape;
  float T = min(sqrt(max(unit_top, 0.0) * sh.x), ceiling);
  float top = T + sh.y * saturate(T / sh.y) * 2.0 * shape_minus_median;
  return saturate((top - h) / sh.z) * saturate(h / sh.w);
}
