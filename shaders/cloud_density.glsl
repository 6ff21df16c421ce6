// Cloud density field (Schneider 2015, "The real-time volumetric cloudscapes of Horizon
// Zero Dawn"; Ford 2024 §3.1, §4.2): coverage from the layer and the global weather map, a
// vertical profile by cloud type, Perlin-Worley base shape and Worley detail erosion. Returns the extinction coefficient sigma_t in 1/m.
// Needs frame_uniforms.glsl, common.glsl and weather_map_sampling.glsl.
// Cumulus layers drawn as individual domes (CloudLayerGpu.dome, weather/cumulus_domes.h)
// read their tops through cumulus_domes.glsl; programs compiled without
// CLOUDSVC_CUMULUS_DOMES (renderer/density_programs.h) hold none of that code. With
// CLOUDSVC_NOISE_TILING (RendererConfig::noise_tiling) both noise volumes are read through
// their stochastic tiling (noise_tiling.glsl), so the field does not repeat with their period.
#ifdef CLOUDSVC_CUMULUS_DOMES
#include "gradient_noise.glsl"
#include "cumulus_domes.glsl"
#endif

layout(binding = TEX_BASE_NOISE) uniform sampler3D base_noise;      // tiles (REPEAT)
layout(binding = TEX_DETAIL_NOISE) uniform sampler3D detail_noise;  // tiles (REPEAT)
// the base noise's max pyramid: mip level l holds the largest texel of each 2^l block
// (weather/noise_max_pyramid.h); read with texelFetch
layout(binding = TEX_BASE_NOISE_MAX) uniform sampler3D base_noise_max;

uint g_density_evals = 0u;  // per-invocation count of density evaluations

// The weather map at p (local frame; indexed by the latitude / longitude of the point's
// direction from the shell centre, in ECEF axes) as layer li reads it: for a layer with a
// layer-coverage channel (forecast weather, CloudLayerGpu.coverage_channel >= 0) its R holds
// that channel's coverage, which local_coverage takes as it is; other layers read the
// map's coverage modulation.
vec4 layer_weather_at(int li, vec3 p) {
  vec3 q = from_shell_centre(p);
  vec4 w = weather_map_at(q, frame.weather_map_height, frame.weather_blend, frame.weather_pole_south, frame.weather_pole_north);
  int channel = frame.layers[li].coverage_channel;
  if (channel >= 0) {
    vec4 c = layer_coverage_map_at(q, frame.weather_map_height, frame.weather_blend, frame.layer_coverage_pole_south,
                                   frame.layer_coverage_pole_north);
    w.r = c[channel];
  }
  return w;
}

// Fraction of the layer's depth the clouds fill at weather w: the cloud-type channel
// t = w.g (the protocol's vertical development): 0.5 = full layer depth, less = lower
// tops; stratiform sheets (base_offset.w = 1) are not driven by it
// (weather::type_depth_fraction / type_height_profile, weather/cloud_layer.h).
float depth_fraction(CloudLayerGpu L, vec4 w) { return L.stratiform != 0 ? 1.0 : clamp(0.5 + w.g, 0.3, 1.0); }

// Vertical profile over the height fraction f of the layer (0 base, 1 top).
float height_profile(CloudLayerGpu L, float f) {
  float bottom = smoothstep(0.0, max(L.bottom_ramp, 1e-3), f);
  float top = 1.0 - smoothstep(1.0 - max(L.top_ramp, 1e-3), 1.0, f);
  return bottom * top * mix(1.0, f, L.top_weight);
}

// An upper bound of height_profile over [fa, fb] from its factors' monotonicity: the
// rising ramp at fb, the falling ramp at fa, the linear top weighting at its larger end.
float height_profile_max(CloudLayerGpu L, float fa, float fb) {
  return smoothstep(0.0, max(L.bottom_ramp, 1e-3), fb) * (1.0 - smoothstep(1.0 - max(L.top_ramp, 1e-3), 1.0, fa)) *
         max(mix(1.0, fa, L.top_weight), mix(1.0, fb, L.top_weight));
}

// Base-noise value below which a fraction p of the volume lies (piecewise linear in the
// 16 quantiles measured on the CPU when the noise was generated).
float noise_quantile(float p) {
  float x = saturate(p) * 15.0;
  int i = min(int(x), 14);
  float a = frame.noise_quantiles[i / 4][i % 4];
  float b = frame.noise_quantiles[(i + 1) / 4][(i + 1) % 4];
  return mix(a, b, x - float(i));
}

// Width of the soft edge of the coverage threshold, in base-noise units.
const float COVERAGE_EDGE = 0.12;

// Local coverage of a layer where it reads the weather w (layer_weather_at): the layer's
// coverage modulated by the map's R, or its coverage channel's value as it is
// (weather::layer_local_coverage, weather/weather_map.h). With an upper bound of the map's
// value in w.r, an upper bound.
float local_coverage(CloudLayerGpu L, vec4 w) {
  return L.coverage_channel >= 0 ? clamp(w.r, 0.0, 1.0) : modulated_coverage(L.coverage, w.r);
}

// The anvil of a convective layer (weather::Anvil, weather/cloud_layer.h): its weight at
// the layer's height fraction f, rising over the lowest fifth of the band [base, top] and
// falling over its top fifth (0 outside the band and for layers without an anvil).
float anvil_weight(CloudLayerGpu L, float f) {
  if (L.anvil.x <= 0.0) return 0.0;
  float r = 0.2 * (L.anvil.z - L.anvil.y);
  return smoothstep(L.anvil.y, L.anvil.y + r, f) * (1.0 - smoothstep(L.anvil.z - r, L.anvil.z, f));
}

// Largest anvil_weight over [f0, f1]: the weight rises to a plateau around the band's
// middle and falls after it, so its maximum is at the interval's point nearest that middle.
float anvil_weight_max(CloudLayerGpu L, float f0, float f1) {
  return anvil_weight(L, clamp(0.5 * (L.anvil.y + L.anvil.z), f0, f1));
}

// The shield's wider coverage 1 - (1 - c)^(1 + spread w) (c where w = 0; 0 stays 0).
float anvil_coverage(CloudLayerGpu L, float c, float w) { return 1.0 - pow(1.0 - c, 1.0 + L.anvil.x * w); }

// How cloud_extinction treats the detail noise: not at all (light marches and ground
// shadows, which see only the base shape), sampled, or replaced by its mean value (level
// of detail: where a pixel's footprint spans several detail texels their erosion averages
// out; the mean keeps the mean density instead of dropping the erosion).
const int DETAIL_NONE = 0;
const int DETAIL_SAMPLED = 1;
const int DETAIL_MEAN = 2;

// Noise space f(X) = X + (k - 1) a(X) n(X): altitude a scaled by k along the local up n, a
// fixed map of the world; camera-relative: f(X) - f(X_cam) = p + (k - 1)(a n - h n_cam).
// Returned in the wind-rotated field's axes (m).
vec3 field_point(CloudLayerGpu L, vec3 p, float alt) {
  vec3 p_stretched = p + (L.noise_vertical_scale - 1.0) * (alt * up_at(p, frame.shell_radius_m, frame.camera_altitude_m) - vec3(0.0, 0.0, frame.camera_altitude_m));
  return mat3(L.noise_rotation) * p_stretched;
}

// Largest value a trilinear sample of the base noise can take anywhere in the box
// [u_lo, u_hi] of texture coordinates (1 = one period): the texels such a sample reads
// are covered by at most 2 x 2 x 2 cells of the finest max-pyramid level whose cells are
// as large as the box (NoiseMaxPyramid::max_over, the same walk).
float base_noise_max_over(vec3 u_lo, vec3 u_hi) {
  int n0 = textureSize(base_noise_max, 0).x;
  int top = textureQueryLevels(base_noise_max) - 1;
  float global_max = texelFetch(base_noise_max, ivec3(0), top).r;
  ivec3 lo, hi;
  int level = 0;
  for (int a = 0; a < 3; ++a) {
    float shift = floor(u_lo[a]);
    float x0 = (u_lo[a] - shift) * float(n0) - 0.5, x1 = (u_hi[a] - shift) * float(n0) - 0.5;
    if (!(x1 - x0 < float(n0))) return global_max;  // spans a period
    lo[a] = int(floor(x0));
    hi[a] = int(floor(x1)) + 1;
    while ((hi[a] >> level) - (lo[a] >> level) > 1) ++level;  // >> floors negatives (sign-extending)
  }
  if (level >= top) return global_max;
  int mask = (n0 >> level) - 1;  // wrap: the level's edge is a power of two
  float best = 0.0;
  for (int z = lo.z >> level; z <= hi.z >> level; ++z)
    for (int y = lo.y >> level; y <= hi.y >> level; ++y)
      for (int x = lo.x >> level; x <= hi.x >> level; ++x)
        best = max(best, texelFetch(base_noise_max, ivec3(x, y, z) & mask, level).r);
  return best;
}

#ifdef CLOUDSVC_NOISE_TILING
#include "noise_tiling.glsl"
#endif

// A noise volume at s (periods, camera-relative as CloudLayerGpu.*_noise_offset), through
// its tiling where compiled with it (the camera's cell, the lattices' seeds, the mean).
float noise_at(sampler3D volume, vec3 s, ivec3 camera_cell, uvec4 seeds, float mean) {
#ifdef CLOUDSVC_NOISE_TILING
  return tiled_noise(volume, s, camera_cell, seeds, mean);
#else
  return textureLod(volume, s, 0.0).r;
#endif
}

// An upper bound of layer L's base-shape noise over the box [s_lo, s_hi].
float base_shape_max_over(CloudLayerGpu L, vec3 s_lo, vec3 s_hi) {
#ifdef CLOUDSVC_NOISE_TILING
  return tiled_base_noise_max_over(L, s_lo, s_hi);
#else
  return base_noise_max_over(s_lo, s_hi);
#endif
}

// Whether layer li can have cloud anywhere on the segment a..b (local frame, m; a few
// hundred m at most) with the weather w read at one end: false only where the density is
// 0 on all of it (the long-step probes of the march skip such a segment). Bounds: the
// base noise by its max pyramid over the segment's noise-space box; the height profile by
// its factors' monotonicity (rising ramp at the segment's highest height fraction, falling
// ramp at its lowest); the coverage and cloud type of the weather map are those of w (the
// map's texels are tens of km; a segment is a small fraction of one).
bool cloud_may_be_on_segment(int li, vec3 a, vec3 b, vec4 w) {
  CloudLayerGpu L = frame.layers[li];
  float coverage = local_coverage(L, w);
  if (coverage <= 0.0) return false;
  float R = frame.shell_radius_m, h = frame.camera_altitude_m;
  float alt_a = altitude_of(a, R, h), alt_b = altitude_of(b, R, h);
  float span = (L.top_m - L.base_m) * depth_fraction(L, w);
  // the segment's heights above the base (1 m of slack: the ray's altitude between the ends)
  float h_lo = min(alt_a, alt_b) - 1.0 - L.base_m, h_hi = max(alt_a, alt_b) + 1.0 - L.base_m;
  // domes: anywhere between the base and the ceiling raised by the cauliflower tops (a
  // bound by height only)
#ifdef CLOUDSVC_CUMULUS_DOMES
  if (L.dome != 0) return h_hi > 0.0 && h_lo < span + dome_layers[li].shape.y;
#endif
  float g0 = h_lo / span, g1 = h_hi / span;  // height fractions of the profile
  if (g1 <= 0.0 || g0 >= 1.0) return false;
  // the anvil widens the coverage (never narrows it): its largest weight over the layer's
  // height fractions of the segment
  float thickness = L.top_m - L.base_m;
  coverage = anvil_coverage(L, coverage, anvil_weight_max(L, h_lo / thickness, h_hi / thickness));
  float profile_bound = height_profile_max(L, max(g0, 0.0), min(g1, 1.0));
  vec3 ua = field_point(L, a, alt_a) * L.base_noise_frequency + L.base_noise_offset;
  vec3 ub = field_point(L, b, alt_b) * L.base_noise_frequency + L.base_noise_offset;
  float pad = 0.05 / float(textureSize(base_noise_max, 0).x);  // the stretch's curvature between the ends
  float shape_bound = base_shape_max_over(L, min(ua, ub) - pad, max(ua, ub) + pad);
  return shape_bound * profile_bound > noise_quantile(1.0 - coverage);
}

// sigma_t per unit cloud fraction (1/m) of layer L where the map reads w: its density scale,
// the map's density modulation 2^(2 (w.b - 1/2)) and its peak extinction
// (CloudField::extinction_scale).
float extinction_scale(CloudLayerGpu L, vec4 w) { return L.density_scale * exp2(2.0 * (w.b - 0.5)) * L.extinction_max; }

// The base-shape noise of layer L at field point p_field (field_point).
float base_shape_at(CloudLayerGpu L, vec3 p_field) {
  return noise_at(base_noise, p_field * L.base_noise_frequency + L.base_noise_offset, L.base_noise_cell,
                  L.base_tiling_seeds, frame.base_noise_mean);
}

// The textured base of a sheet (CloudTypeTraits::base_relief r; CloudField::base_lift and
// base_lift_factor, the same rules): the lift of layer L's base, as a fraction of its depth,
// where the detail noise reads D: r saturate(BASE_LIFT_MEAN + D - mean(D)), r BASE_LIFT_MEAN
// at the mean (the base-shape field of light marches, columns and ground shadows, and the
// level of detail); and the factor on the height profile at height fraction f over a base
// lifted by `lift`, the cloud fading in over the layer's bottom ramp above it (1 in layers
// without relief; at most 1, so every bound of the profile holds with it).
float base_lift(CloudLayerGpu L, float detail_value) {
  return L.base_relief * saturate(BASE_LIFT_MEAN + detail_value - frame.detail_noise_mean);
}
float base_lift_factor(CloudLayerGpu L, float f, float lift) {
  return L.base_relief > 0.0 ? smoothstep(lift, lift + max(L.bottom_ramp, 1e-3), f) : 1.0;
}

// The base of layer L's homogeneous layer for the diffuse light (the optical depth below a
// point) and its full nominal optical depth: the base raised by the textured base's mean
// lift (CloudField::nominal_base_m). Where the view meets the lumpy base there is little
// cloud below it: counting the depth the relief removes had made the underside of a stratus
// deck 35 % brighter, where the path-traced truth was 12 % brighter (an earlier, stronger
// relief; docs/MORPHOLOGY.md, "Textured base").
float nominal_base_m(CloudLayerGpu L) { return L.base_m + L.base_relief * BASE_LIFT_MEAN * (L.top_m - L.base_m); }

// Cloud fraction of a threshold layer (not a dome layer) with base shape `shape` at height
// fraction f of the layer, where the profile is `profile`, the local coverage c and its
// threshold q = noise_quantile(1 - c); anvil_factor returns the anvil's extinction factor
// (1 outside its band). CloudField::threshold_fraction (renderer/reference) is the same.
float threshold_fraction(CloudLayerGpu L, float f, float profile, float coverage, float q, float shape,
                         out float anvil_factor) {
  // Coverage threshold: the shape exceeds Q(1 - c) over a fraction c of the area (at
  // mid-profile), with a soft edge; full cover (c = 1) keeps nearly all of the shape.
  float d = saturate((shape * profile - q) / COVERAGE_EDGE);
  anvil_factor = 1.0;
  // In an anvil's band the cloud fills the wider coverage c_w too, the part outside the
  // tower thinner: the extinction factor falls from 1 to density_ratio where the tower's
  // own d is 0, by the anvil's weight w (1 again where w = 0: continuous at the band's edges).
  float w_anvil = anvil_weight(L, f);
  if (w_anvil > 0.0) {
    float d_shield = saturate((shape * profile - noise_quantile(1.0 - anvil_coverage(L, coverage, w_anvil))) / COVERAGE_EDGE);
    anvil_factor = 1.0 - w_anvil * (1.0 - L.anvil.w) * (1.0 - d);
    d = max(d, d_shield);
  }
  return d;
}

#ifdef CLOUDSVC_CUMULUS_DOMES
// Cloud fraction of dome layer li (weather/cumulus_domes.h) at local point p, h m above its
// base, with local coverage c, ceiling (m above the base) and the base-shape noise value
// `shape` there: the dome fraction under the layer's top with cauliflower tops from the
// shape noise. The placement's field point is unstretched: q = camera_q + W E p
// (noise_rotation is S W E, and S = I for cumulus: weather/noise_shaping.h).
float dome_cloud_fraction(int li, CloudLayerGpu L, vec3 p, float h, float c, float ceiling, float shape) {
  if (h >= ceiling + dome_layers[li].shape.y) return 0.0;
  vec3 q = dome_layers[li].camera_q.xyz + mat3(L.noise_rotation) * p;
  float unit_top = dome_top(li, q, c);
  if (unit_top <= 0.0) return 0.0;
  return dome_fraction(li, unit_top, ceiling, h, shape - noise_quantile(0.5));
}
#endif

// sigma_t (1/m) of layer li at local point p with altitude alt, where the weather map
// reads w (layer_weather_at; the light march passes its sample's value: the map's texels are
// ~40 km, a light march spans at most LIGHT_MARCH_REACH_M, 4 km); also returns the local
// coverage (0 outside the layer). The cloud fraction d comes from the layer's model (a dome
// layer's domes, or the noise threshold below); both read the base-shape noise once, and
// the detail erosion and density follow for either. (On llvmpipe both models run for
// every layer, docs/PERFORMANCE.md: the reads they share are made once.)
float cloud_extinction_in(int li, vec3 p, float alt, int detail, vec4 w, out float coverage) {
  coverage = 0.0;
  CloudLayerGpu L = frame.layers[li];
  float thickness = L.top_m - L.base_m;
  float f = (alt - L.base_m) / thickness;
  if (f <= 0.0 || f >= 1.0) return 0.0;
  g_density_evals += 1u;
  coverage = local_coverage(L, w);
  if (coverage <= 0.0) return 0.0;
  float df = depth_fraction(L, w);
  float profile = height_profile(L, f / df) * step(f, df);
  bool dome = false;
#ifdef CLOUDSVC_CUMULUS_DOMES
  dome = L.dome != 0;
#endif
  if (profile <= 0.0 && !dome) return 0.0;
  vec3 p_field = field_point(L, p, alt);
  float shape = base_shape_at(L, p_field);
  float d;
  float anvil_factor = 1.0;
#ifdef CLOUDSVC_CUMULUS_DOMES
  if (dome) {
    d = dome_cloud_fraction(li, L, p, alt - L.base_m, coverage, df * thickness, shape);
  } else
#endif
  {
    d = threshold_fraction(L, f, profile, coverage, noise_quantile(1.0 - coverage), shape, anvil_factor);
  }
  if (d <= 0.0) return 0.0;
  // The detail noise where it is sampled and the cloud fraction is partial (its edges) or a
  // textured base may lift it; its mean elsewhere (level of detail, and the base-shape
  // field's lift). The textured base recomputes the fraction over the lifted profile (one
  // read of the detail noise: llvmpipe runs a branch's reads whether a lane takes it or not).
  bool in_relief = L.base_relief > 0.0 && f < L.base_relief + L.bottom_ramp;
  float dn = frame.detail_noise_mean;
  if (detail == DETAIL_SAMPLED && (d < 1.0 || in_relief))
    dn = noise_at(detail_noise, p_field * L.detail_noise_frequency + L.detail_noise_offset, L.detail_noise_cell,
                  L.detail_tiling_seeds, frame.detail_noise_mean);
  if (in_relief && !dome) {
    d = threshold_fraction(L, f, profile * base_lift_factor(L, f, base_lift(L, dn)), coverage, noise_quantile(1.0 - coverage),
                           shape, anvil_factor);
    if (d <= 0.0) return 0.0;
  }
  if (detail != DETAIL_NONE && d < 1.0) d = saturate(remap(d, dn * L.detail_erosion, 1.0, 0.0, 1.0));
  return d * anvil_factor * extinction_scale(L, w);
}

// The same where the weather is read at p itself.
float cloud_extinction(int li, vec3 p, float alt, int detail, out float coverage) {
  CloudLayerGpu L = frame.layers[li];
  float f = (alt - L.base_m) / (L.top_m - L.base_m);
  coverage = 0.0;
  if (f <= 0.0 || f >= 1.0) return 0.0;
  return cloud_extinction_in(li, p, alt, detail, layer_weather_at(li, p), coverage);
}

float cloud_extinction(int li, vec3 p, float alt, int detail) {
  float coverage;
  return cloud_extinction(li, p, alt, detail, coverage);
}
