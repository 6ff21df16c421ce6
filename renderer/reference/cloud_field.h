// The cloud density field of the model (docs/RENDERING.md "Cloud density"; Schneider 2015
// / Nubis, as in Ford 2024 §3.1 and §4.2), evaluated in double precision from the shared inputs with
// emulated GL sampling (texture_sampling.h). For a local point p at altitude a inside
// layer L (base b, top t), f = (a - b) / (t - b):
//   1. weather map w at the latitude/longitude of p's direction from the shell centre
//      (ECEF axes; atan2 for both angles), with the pole blend;
//      local coverage c = clamp(c_L + 1.2 min(c_L, 1 - c_L)(2 w.r - 1), 0, 1);
//   2. depth fraction f_v = clamp(0.5 + w.g, 0.3, 1) of the cloud-type channel G
//      (weather::type_depth_fraction; see honour_stratiform below),
//      profile P = H(f / f_v) [f <= f_v], H(x) = smoothstep(0, r_b, x)
//      (1 - smoothstep(1 - r_t, 1, x)) mix(1, x, top_weight), ramps floored at 1e-3;
//   3. base shape S = trilinear base noise at (field position) / base period (with
//      noise_tiling: through its stochastic tiling, weather/noise_tiling.h), where the
//      field position is the wind-rotated ECEF position with the altitude scaled by the
//      type's noise vertical scale k: R (X + (k - 1) a n), n the shell's up at the point
//      (k < 1 stretches features upwards: convective towers);
//      d = saturate((S P - Q(1 - c)) / 0.12), Q the base noise's quantile function;
//      with a textured base (the layer's base_relief r > 0, the type's) and f < r + r_b,
//      d is that of the lifted profile P smoothstep(l, l + r_b, f), l = r saturate(0.5 + D -
//      mean(D)) (base_lift; D the detail noise at the point where detail is wanted, its
//      mean otherwise: the base-shape field of the light is lifted by r / 2);
//   4. anvil (weather::Anvil; layers with spread > 0): with its weight w = W(f) > 0, the
//      shield's d_s = saturate((S P - Q(1 - c_w)) / 0.12), c_w = 1 - (1 - c)^(1 + spread w);
//      factor a = 1 - w (1 - density_ratio)(1 - d), then d = max(d, d_s) (a = 1 elsewhere);
//   5. where 0 < d < 1 and detail is wanted: D = trilinear detail noise at
//      (field position) / detail period (tiled as in 3 with noise_tiling), d = saturate((d - D e) / (1 - D e)), e = erosion;
//   6. sigma_t = d * a * density_scale * 2^(2 (w.b - 0.5)) * sigma_max (1/m).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/reference/reference_inputs.h"
#include "renderer/reference/reference_scene.h"

namespace cloudsvc::reference {

constexpr double kCoverageEdge = 0.12;  // soft edge of the coverage threshold, base-noise units

struct CloudSample {
  double sigma_t = 0.0;   // extinction, 1/m
  double coverage = 0.0;  // local coverage c (0 outside the layer or where the map clears it)
};

class CloudField {
 public:
  // honour_stratiform: when true (the model's definition, as in the shader), stratiform
  // layers ignore the weather map's cloud-type channel G (f_v = 1), as
  // weather/cloud_layer.h and docs/WEATHER.md describe them; false applies f_v to every
  // layer, for comparisons (docs/REFERENCE.md, "GPU vs reference").
  // cumulus_domes: cumulus layers as individual domes (weather/cumulus_domes.h), read through
  // the rings the GPU would place for this camera (weather::DomeTopSampler), as the renderer
  // does with RendererConfig::cumulus_domes.
  // noise_tiling: both noise volumes read through their stochastic tiling
  // (weather/noise_tiling.h), as the renderer does with RendererConfig::noise_tiling.
  CloudField(const ReferenceScene& scene, const ReferenceInputs& inputs, bool honour_stratiform = true,
             bool cumulus_domes = false, bool noise_tiling = false);
  ~CloudField();

  // Extinction of layer li at local point p with altitude alt (above the shell sphere).
  // Increments evals when the point lies inside the layer's altitude range (the same
  // counting rule as the GPU's density_evals).
  CloudSample sample(int li, const glm::dvec3& p, double alt, bool detail, std::uint64_t& evals) const;

  // Optical depths (below, above) of layer li's vertical column through local point p
  // (altitude alt): down to the layer's base, and up to where its profile ends
  // (profile_top_m), without the detail erosion (docs/RENDERING.md "Column volume"), each
  // part in steps_for(its length in m) steps. The base shape S is read at the steps' ends
  // (at p once for both parts) and taken linear between them; the profile P at
  // model::kColumnPiecesPerStep points per step; over each piece g = (S P - Q(1 - c)) / 0.12
  // is linear and the mean of saturate(g) exact (saturate_mean). Anvil layers take saturate
  // at the pieces' midpoints (their shield's threshold varies with height), dome layers the
  // full sample there. The weather map is read once, at p: the column is vertical. The
  // GPU's marched_column_depths (shaders/column_quadrature.glsl) is the same quadrature.
  glm::dvec2 column_depths(int li, const glm::dvec3& p, double alt, const std::function<int(double)>& steps_for,
                           std::uint64_t& evals) const;
  // Pieces per step of step_m (m) in the column of layer L: model::kColumnPiecesPerStep, and
  // in an anvil layer at least as many per ramp of the anvil's weight (its band's fifth), at
  // most model::kColumnAnvilPiecesMax: at
  // 4 pieces per step, 8 steps per column, the depths above samples in a cumulonimbus's top
  // fifth err by 10 % in their diffuse transmittance, with the ramp's pieces by 2 %
  // (tests/reference_column_depths_test.cpp).
  static int column_pieces(const ReferenceLayer& L, double step_m);
  // The altitude where layer li's profile ends above p: its top scaled by the depth fraction
  // f_v of the map's cloud type there (step 2 of the header); a dome layer's top.
  double profile_top_m(int li, const glm::dvec3& p) const;
  // Mean of saturate(g) over a piece on which g runs linearly from a to b: the difference of
  // the clamped ramp's antiderivative F (0 below 0, x^2 / 2 on [0, 1], x - 1/2 above) over b - a.
  static double saturate_mean(double a, double b);

  // The pieces, for tests: weather map value at p; the vertical profile at height fraction x.
  glm::dvec4 weather_at(const glm::dvec3& p) const;
  static double height_profile(const ReferenceLayer& layer, double x);
  // Step 3's textured base: the lift l (fraction of the depth) where the detail noise reads
  // D, and the factor on the profile at height fraction f over a base lifted by l (1 in
  // layers without relief, else in [0, 1], so every bound of the profile holds with it).
  // The GPU's base_lift and base_lift_factor (shaders/cloud_density.glsl).
  double base_lift(const ReferenceLayer& L, double detail_value) const;
  static double base_lift_factor(const ReferenceLayer& L, double f, double lift);
  // The base of layer L's homogeneous layer for the diffuse light and its nominal optical
  // depth: the base raised by the textured base's mean lift, base_relief x kBaseLiftMean of
  // the depth (the GPU's nominal_base_m; the base itself without relief).
  static double nominal_base_m(const ReferenceLayer& L);
  // The anvil (weather::Anvil): its weight at the layer's height fraction f, the largest
  // weight over [f0, f1] (at the interval's point nearest the band's middle: the weight
  // rises to a plateau there and falls after it), the shield's coverage for c at weight w.
  static double anvil_weight(const ReferenceLayer& layer, double f);
  static double anvil_weight_max(const ReferenceLayer& layer, double f0, double f1);
  static double anvil_coverage(const ReferenceLayer& layer, double c, double w);

  const ReferenceScene& scene() const { return scene_; }
  // The coverage of layer li at a point of its field frame (m): the map read at its direction.
  double coverage_at_field_point(int li, const glm::dvec3& x) const;

 private:
  // The base shape S of step 3 and the detail noise D of step 5 at a field position (m),
  // through the stochastic tiling where noise_tiling (weather/noise_tiling.h; the layer
  // type's tiling seeds).
  double base_shape(const ReferenceLayer& L, const glm::dvec3& field) const;
  double detail_shape(const ReferenceLayer& L, const glm::dvec3& field) const;
  // The noise-field point of local p at altitude alt (step 3: m, wind-rotated ECEF axes, the
  // altitude scaled by k along the local up).
  glm::dvec3 field_point(const ReferenceLayer& L, const glm::dvec3& p, double alt) const;
  // Step 6's factor: sigma_t = d a * extinction_scale (1/m) where the map reads w.
  static double extinction_scale(const ReferenceLayer& L, const glm::dvec4& w);
  // The altitude where layer li's profile ends for depth fraction f_v (profile_top_m).
  double profile_end_m(int li, double f_v) const;
  // f_v of step 2 where the map reads w.
  double depth_fraction(const ReferenceLayer& L, const glm::dvec4& w) const;
  // Steps 3 and 4: the cloud fraction d of base shape S at height fraction f with profile P,
  // local coverage c and threshold q = Q(1 - c), and the anvil's extinction factor a.
  double threshold_fraction(const ReferenceLayer& L, double f, double profile, double coverage, double q, double shape,
                            double& anvil_factor) const;
  struct Domes;
  double dome_fraction(int li, const glm::dvec3& p, double alt, double coverage, double ceiling_m, double shape) const;
  const ReferenceScene& scene_;
  const ReferenceInputs& inputs_;
  bool honour_stratiform_;
  bool noise_tiling_;
  glm::dvec3 centre_to_camera_ecef_;  // shell centre -> camera, ECEF axes, m
  std::vector<std::unique_ptr<Domes>> domes_;  // per layer; null where not drawn as domes
};

}  // namespace cloudsvc::reference
