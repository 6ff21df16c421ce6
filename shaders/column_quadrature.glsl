// The diffuse light's column depths (RenderQuality::column_steps > 0): the optical depths
// (below, above) of a point's own vertical column through its layer, the independent column
// approximation (Cahalan et al. 1994), marched from a lit sample (without the column
// volume) or integrated at the column volume's nodes (column_volume.comp), as the
// reference's column_optical_depths takes them (the same quadrature:
// CloudField::column_depths, renderer/reference/cloud_field.h). Needs cloud_density.glsl.
//
// The cloud fraction saturate((S P - q) / COVERAGE_EDGE) is nearly a step function of
// height, so a midpoint rule with 8 steps errs by 10-35 % in the transmittance of a
// cumulus or cumulonimbus column. Instead the base shape S is read at the steps' ends and
// taken linear between them (the noise is trilinear: smooth over a step), the profile P is
// evaluated at COLUMN_PIECES points per step, and over each piece g = (S P - q) / edge is
// linear and the mean of saturate(g) exact (saturate_mean). Anvil layers take saturate at
// the pieces' midpoints (their shield's threshold varies with height), with at least
// COLUMN_PIECES pieces per ramp of the anvil's weight too; dome layers (their fraction is
// no threshold of S) the full sample at the midpoints of COLUMN_PIECES pieces per step.

// Antiderivative of saturate: 0 below 0, x^2 / 2 on [0, 1], x - 1/2 above.
float saturate_integral(float x) { return x <= 0.0 ? 0.0 : (x < 1.0 ? 0.5 * x * x : x - 0.5); }

// Mean of saturate(g) over a piece on which g runs linearly from a to b (the midpoint's
// value where b - a is too small for the difference quotient; its error there < 1e-7).
float saturate_mean(float a, float b) {
  float d = b - a;
  return abs(d) > 1e-3 ? (saturate_integral(b) - saturate_integral(a)) / d : saturate(0.5 * (a + b));
}

// Pieces per step of length step_m (m, either sign) of an anvil layer's column: at least
// COLUMN_PIECES per ramp of the anvil's weight (anvil_weight: a fifth of its band), at most
// COLUMN_ANVIL_PIECES (CloudField::column_pieces); COLUMN_PIECES in other layers.
int column_step_pieces(CloudLayerGpu L, float step_m) {
  if (L.anvil.x <= 0.0) return COLUMN_PIECES;
  float ramp_m = 0.2 * (L.anvil.z - L.anvil.y) * (L.top_m - L.base_m);
  return clamp(int(ceil(float(COLUMN_PIECES) * abs(step_m) / max(ramp_m, 1.0))), COLUMN_PIECES, COLUMN_ANVIL_PIECES);
}

// The coverage threshold of a column (one weather map value w: the column is vertical):
// the local coverage (<= 0: no cloud in the column), its base-shape quantile q and the
// height span (m) over which the layer's profile runs.
struct ColumnThreshold {
  float coverage;
  float q;
  float span;
};

ColumnThreshold column_threshold(CloudLayerGpu L, vec4 w) {
  ColumnThreshold c;
  c.coverage = local_coverage(L, w);
  c.q = noise_quantile(1.0 - max(c.coverage, 0.0));
  c.span = (L.top_m - L.base_m) * depth_fraction(L, w);
  return c;
}

// The height profile P at height h (m) above layer L's base, over the base-shape field's
// lifted base (a textured base's mean lift: base_lift at the detail noise's mean).
float column_profile(CloudLayerGpu L, ColumnThreshold c, float h) {
  float f = h / (L.top_m - L.base_m);
  return height_profile(L, clamp(h / c.span, 0.0, 1.0)) * base_lift_factor(L, f, base_lift(L, frame.detail_noise_mean));
}

// g = (S P - q) / edge of base shape S at height h (m) above the layer's base: the cloud
// fraction there is saturate(g).
float column_g(CloudLayerGpu L, ColumnThreshold c, float shape, float h) {
  return (shape * column_profile(L, c, h) - c.q) / COVERAGE_EDGE;
}

// One step of a column (base shape only) from fraction t0 to t1 of its signed length len
// from altitude alt along the local vertical: the base shape shape0 at t0 and shape1 at t1,
// taken linear between them; g0: column_g at t0, updated to its value at t1. Returns the
// step's mean cloud fraction times (t1 - t0). c: the column's threshold; pieces:
// column_step_pieces of the step's length (t1 - t0) len.
float column_step(CloudLayerGpu L, float alt, ColumnThreshold c, float shape0, float shape1, inout float g0, float t0,
                  float t1, float len, int pieces) {
  float sum = 0.0;
  // The piece loops have constant bounds, so that the compiler can unroll them: llvmpipe
  // cuts an invocation short after 65535 loop iterations in all, which counted pieces in
  // every column of a long march would pass.
  if (L.anvil.x > 0.0) {
    float thickness = L.top_m - L.base_m;
    float piece = (t1 - t0) / float(pieces);
    for (int k = 0; k < COLUMN_ANVIL_PIECES; ++k) {
      if (k >= pieces) break;
      float u = (float(k) + 0.5) / float(pieces);
      float h = alt + mix(t0, t1, u) * len - L.base_m;  // height above the base at the piece's midpoint
      if (h > 0.0 && h < c.span) {
        float anvil_factor;
        float d = threshold_fraction(L, h / thickness, column_profile(L, c, h), c.coverage, c.q,
                                     mix(shape0, shape1, u), anvil_factor);
        sum += d * anvil_factor * piece;
      }
    }
  } else {
    float piece = (t1 - t0) / float(COLUMN_PIECES);
    for (int k = 1; k <= COLUMN_PIECES; ++k) {
      float u = float(k) / float(COLUMN_PIECES);
      float h = alt + mix(t0, t1, u) * len - L.base_m;
      float g1 = column_g(L, c, mix(shape0, shape1, u), h);
      sum += saturate_mean(g0, g1) * piece;
      g0 = g1;
    }
  }
  return sum;
}

// The part of layer L's column from p (altitude alt) along the local vertical up (along it
// the altitude is alt + s) over the signed length len (> 0 upwards), base shape only, in n
// steps (column_step), as the mean cloud fraction times the length (m;
// marched_column_depths scales it to an optical depth). c: the column's threshold;
// shape_p, g_p: the base shape at p and its column_g (read once for both parts). The nodes
// lie at fractions clamp((j + offset - 1/2) / n, 0, 1) of the length, j = 0..n+1: offset
// 1/2 puts them at the steps' ends;
// cloud_march.comp moves offset from frame to frame, so a still camera's accumulated
// samples integrate the column as more steps would (n + 1 base-shape reads then, n at
// offset 1/2).
float column_part(CloudLayerGpu L, vec3 p, float alt, vec3 up, ColumnThreshold c, float shape_p, float g_p, float len,
                  int n, float offset) {
  if (n <= 0 || len == 0.0) return 0.0;
  int pieces = column_step_pieces(L, len / float(n));
  float shape0 = shape_p, g0 = g_p;
  float t0 = 0.0, sum = 0.0;
  for (int j = 1; j <= n + 1; ++j) {
    float t1 = clamp((float(j) + offset - 0.5) / float(n), 0.0, 1.0);
    if (t1 <= t0) break;
    g_density_evals += 1u;
    float shape1 = base_shape_at(L, field_point(L, p + up * (t1 * len), alt + t1 * len));
    sum += column_step(L, alt, c, shape0, shape1, g0, t0, t1, len, pieces);
    shape0 = shape1;
    t0 = t1;
  }
  return sum * abs(len);
}

#ifdef CLOUDSVC_CUMULUS_DOMES
// The same part's optical depth in a dome layer: the full sample at the midpoints of
// COLUMN_PIECES pieces per step (the domes' fraction is no threshold of the shape).
float dome_column_part(int li, vec3 p, float alt, vec3 up, vec4 w, float len, int n, float offset) {
  int m = n * COLUMN_PIECES;
  float tau = 0.0, c;
  for (int i = 0; i < m; ++i) {
    float s = (float(i) + offset) / float(m) * len;
    tau += cloud_extinction_in(li, p + up * s, alt + s, DETAIL_NONE, w, c);
  }
  return m > 0 ? tau * abs(len) / float(m) : 0.0;
}
#endif

// The column depths (below, above) of a lit sample of layer li at p (altitude alt, local
// vertical up, weather map value w): the column from the layer's base to where its profile
// ends (the top scaled by the depth fraction of the map's cloud type: height_profile is 0
// above it) gets n steps, shared between the parts below and above alt by their lengths.
// n = 0 marches nothing (llvmpipe runs the caller's untaken branch with its lanes masked).
vec2 marched_column_depths(int li, vec3 p, float alt, vec3 up, vec4 w, int n, float offset) {
  CloudLayerGpu L = frame.layers[li];
  ColumnThreshold c = column_threshold(L, w);
  float top = L.base_m + c.span;
#ifdef CLOUDSVC_CUMULUS_DOMES
  if (L.dome != 0) top = L.top_m;  // cauliflower tops rise above the profile's end
#endif
  float len_above = max(top - alt, 0.0), len_below = max(alt - L.base_m, 0.0);
  float H = max(len_above + len_below, 1.0);
  int n_above = n > 0 ? max(int(ceil(float(n) * len_above / H)), 1) : 0;
  int n_below = n > 0 ? max(int(ceil(float(n) * len_below / H)), 1) : 0;
#ifdef CLOUDSVC_CUMULUS_DOMES
  if (L.dome != 0)
    return vec2(dome_column_part(li, p, alt, up, w, -len_below, n_below, offset),
                dome_column_part(li, p, alt, up, w, len_above, n_above, offset));
#endif
  if (n <= 0 || c.coverage <= 0.0) return vec2(0.0);
  g_density_evals += 1u;
  float shape_p = base_shape_at(L, field_point(L, p, alt));
  float g_p = column_g(L, c, shape_p, alt - L.base_m);
  return extinction_scale(L, w) * vec2(column_part(L, p, alt, up, c, shape_p, g_p, -len_below, n_below, offset),
                                       column_part(L, p, alt, up, c, shape_p, g_p, len_above, n_above, offset));
}
