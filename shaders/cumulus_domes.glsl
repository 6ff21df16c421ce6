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

// Loops on the way from a density evaluation to a dome top: llvmpipe caps the loop
// iterations of an invocation (count_if_loops_capped, frame_counters.glsl), a loop costs
// iterations even in a branch no lane takes, and a density evaluation sits inside every
// light-march step; but a loop is also llvmpipe's only way to skip code (it runs both
// sides of every branch, docs/PERFORMANCE.md): it ends once no lane of the SIMD batch
// needs another iteration. The sub-grid levels are therefore summed in a loop over the
// levels the point needs where the quality's marches leave the budget for it
// (CLOUDSVC_DENSITY_LOOPS, renderer/density_programs.h), and written out otherwise; the
// rings are always written out.

// Octave i of the sub-grid noise (weighted) at the shell point s (relative to A).
float dome_subgrid_octave(int slot, int i, vec3 s) {
  vec3 r = vec3(dot(dome_layers[slot].oct_rot[3 * i].xyz, s), dot(dome_layers[slot].oct_rot[3 * i + 1].xyz, s), dot(dome_layers[slot].oct_rot[3 * i + 2].xyz, s));
  return dome_layers[slot].oct_rot[3 * i].w * perlin_noise_at(dome_layers[slot].oct_cell[i].xyz, dome_layers[slot].oct_frac[i].xyz + r * dome_layers[slot].oct_frac[i].w, uint(dome_layers[slot].oct_cell[i].w));
}

// The two octaves of level l of the sub-grid noise, 0 where l >= levels (a step of
// dome_top's prefix sums).
float dome_subgrid_level(int slot, int l, vec3 s, int levels) {
  return l < levels ? dome_subgrid_octave(slot, 2 * l, s) + dome_subgrid_octave(slot, 2 * l + 1, s) : 0.0;
}

float dome_subgrid_quantile(int slot, float p, int levels) {
  float x = clamp(p, 0.0, 1.0) * float(DOME_QUANTILES);
  int i = min(int(x), DOME_QUANTILES - 1);
  int row = levels * (DOME_QUANTILES + 1);
  return mix(dome_layers[slot].quantile[row + i], dome_layers[slot].quantile[row + i + 1], x - float(i));
}

// DomeSubgrid::top_m over the first `levels` levels, from their noise sum n
float dome_subgrid_top(int slot, float n, int levels, float covered) {
  float floor_m = dome_layers[slot].params.x;
  if (levels <= 0 || covered <= 0.0) return -floor_m;
  float t = dome_layers[slot].params.y * (n - dome_subgrid_quantile(slot, 1.0 - covered, levels)) / dome_layers[slot].rms[levels];
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

// Ring k's part of dome_top: where the ring exists and covers uv, its share (its weight of
// what the finer rings left), its bilinear reading, and the sub-grid levels it needs.
void dome_ring_share(int slot, int k, vec2 uv, out float share, out vec2 reading, inout float remaining, inout int needed) {
  share = 0.0;
  reading = vec2(0.0);
  if (k >= dome_layers[slot].info.x || remaining <= 0.0) return;
  float w = dome_ring_weight(slot, k, uv);
  if (w <= 0.0) return;
  reading = dome_ring_bilinear(slot, k, uv);
  share = remaining * w;
  remaining -= share;
  needed = max(needed, int(dome_layers[slot].ring[k].w));
}

// Ring k's weighted top: the max of its reading and the sub-grid of the levels it does not draw.
float dome_ring_top(int slot, int k, float share, vec2 reading, float prefix[DOME_LEVELS + 1]) {
  if (share <= 0.0) return 0.0;
  int levels = int(dome_layers[slot].ring[k].w);
  return share * max(reading.x, dome_subgrid_top(slot, prefix[levels], levels, reading.y));
}

// The unit-aspect dome top (m) of dome layer `slot` above or below q (relative to the
// anchor, field frame); coverage_here: the layer's coverage there (for the sub-grid beyond
// the last ring). Each ring, finest first, takes its weight of what the finer ones left;
// the sub-grid noise is summed once, over the most levels any of them needs.
float dome_top(int slot, vec3 q, float coverage_here) {
  vec2 uv = dome_plane_coords(slot, q);
  vec3 s = dome_shell_point(slot, q);
  vec4 weight = vec4(0.0);  // ring k's share: its blend weight times what the finer rings left
  vec2 reading[DOME_RINGS] = vec2[DOME_RINGS](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
  float remaining = 1.0;
  int needed = 0;  // sub-grid levels needed
  dome_ring_share(slot, 0, uv, weight[0], reading[0], remaining, needed);
  dome_ring_share(slot, 1, uv, weight[1], reading[1], remaining, needed);
  dome_ring_share(slot, 2, uv, weight[2], reading[2], remaining, needed);
  dome_ring_share(slot, 3, uv, weight[3], reading[3], remaining, needed);
  int all_levels = dome_layers[slot].info.w;
  if (remaining > 0.0) needed = all_levels;
  // prefix sums of the sub-grid noise: prefix[l] over the first l levels (DOME_LEVELS = 4)
  float prefix[DOME_LEVELS + 1] = float[DOME_LEVELS + 1](0.0, 0.0, 0.0, 0.0, 0.0);
#ifdef CLOUDSVC_DENSITY_LOOPS
  for (int l = 0; l < needed; ++l) prefix[l + 1] = prefix[l] + dome_subgrid_level(slot, l, s, needed);
#else
  prefix[1] = prefix[0] + dome_subgrid_level(slot, 0, s, needed);
  prefix[2] = prefix[1] + dome_subgrid_level(slot, 1, s, needed);
  prefix[3] = prefix[2] + dome_subgrid_level(slot, 2, s, needed);
  prefix[4] = prefix[3] + dome_subgrid_level(slot, 3, s, needed);
#endif
  float result = dome_ring_top(slot, 0, weight[0], reading[0], prefix) + dome_ring_top(slot, 1, weight[1], reading[1], prefix) +
                 dome_ring_top(slot, 2, weight[2], reading[2], prefix) + dome_ring_top(slot, 3, weight[3], reading[3], prefix);
  // over every level the covered fraction is the coverage itself (up to the placement's max)
  if (remaining > 0.0)
    result += remaining * dome_subgrid_top(slot, prefix[all_levels], all_levels, min(coverage_here, dome_layers[slot].params.z));
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
