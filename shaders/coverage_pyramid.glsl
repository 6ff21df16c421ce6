// The coverage max-pyramid of the weather map (renderer/coverage_pyramid.h, built on the
// CPU from both keyframes): the largest coverage modulation m the map can give anywhere in
// a cap on the shell sphere, from at most 3 x 3 cells of one level (twice across the
// antimeridian). Mirrors pyramid_max_in_cap of renderer/coverage_pyramid.cpp (held to
// it by tests/gpu_coverage_pyramid_test.cpp). Needs common.glsl.

layout(std430, binding = SSBO_COVERAGE_PYRAMID) readonly buffer CoveragePyramid {
  ivec4 cp_level[16];  // kGpuPyramidLevels (renderer/coverage_pyramid.h); per level: x width, y height (cells), z offset of its first cell; cp_level[0].w = levels
  float cp_cell[];     // row-major per level, rows from the south
} CP;

// Largest cell of level k over cells [i0, i1] x [r0, r1] of that level (at most 3 x 3).
float cp_max_over(int k, int i0, int i1, int r0, int r1) {
  ivec4 l = CP.cp_level[k];
  float m = 0.0;
  for (int r = r0; r <= r1; ++r)
    for (int i = i0; i <= i1; ++i) m = max(m, CP.cp_cell[l.z + r * l.x + i]);
  return m;
}

// Level-0 cell ranges [i0, i1] x [r0, r1] (0 <= i0 <= i1 < width) at the finest level at
// which they span at most three cells per axis.
float cp_max_in_range(int i0, int i1, int r0, int r1) {
  int top = CP.cp_level[0].w - 1, k = 0;
  while (k < top && ((i1 >> k) - (i0 >> k) > 2 || (r1 >> k) - (r0 >> k) > 2)) ++k;
  return cp_max_over(k, i0 >> k, i1 >> k, r0 >> k, r1 >> k);
}

// Largest m within angular distance a (rad) of latitude lat, longitude lon (rad).
float pyramid_max_in_cap(float lat, float lon, float a) {
  int W = CP.cp_level[0].x, H = CP.cp_level[0].y - 1;
  const float EDGE = 1.0 / 16.0;  // texels: the sampler's sub-texel precision
  float y_lo = ((lat - a) / PI + 0.5) * float(H) - EDGE;
  float y_hi = ((lat + a) / PI + 0.5) * float(H) + EDGE;
  int r0 = clamp(int(floor(y_lo + 0.5)), 0, H), r1 = clamp(int(floor(y_hi + 0.5)), 0, H);
  float s = sin(a) / cos(lat);
  if (lat - a <= -0.5 * PI || lat + a >= 0.5 * PI || !(s < 1.0)) return cp_max_in_range(0, W - 1, r0, r1);
  float dl = asin(s);
  float x_lo = ((lon - dl) / (2.0 * PI) + 0.5) * float(W) - EDGE;
  float x_hi = ((lon + dl) / (2.0 * PI) + 0.5) * float(W) + EDGE;
  int i0 = int(floor(x_lo - 0.5)), i1 = int(floor(x_hi - 0.5));
  if (i1 - i0 + 1 >= W) return cp_max_in_range(0, W - 1, r0, r1);
  if (i0 < 0) { i0 += W; i1 += W; }
  if (i0 >= W) { i0 -= W; i1 -= W; }
  if (i1 < W) return cp_max_in_range(i0, i1, r0, r1);
  return max(cp_max_in_range(i0, W - 1, r0, r1), cp_max_in_range(0, i1 - W, r0, r1));
}
