// Cloud density field of the reference (see cloud_field.h).
#include "renderer/reference/cloud_field.h"

#include "weather/cloud_layer.h"
#include "weather/cumulus_domes.h"
#include "weather/dome_rings.h"
#include "weather/noise_tiling.h"
#include "weather/weather_map.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/model/scene_constants.h"
#include "renderer/reference/texture_sampling.h"

namespace cloudsvc::reference {

namespace {

double saturate(double x) { return std::clamp(x, 0.0, 1.0); }

// GLSL smoothstep(e0, e1, x): t = clamp((x - e0) / (e1 - e0), 0, 1), t^2 (3 - 2 t).
double smoothstep(double e0, double e1, double x) {
  const double t = saturate((x - e0) / (e1 - e0));
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

// A dome layer's placement, warp, sub-grid, the rings for this camera and their reader.
struct CloudField::Domes {
  weather::CloudPlacement placement;
  weather::DomeWarp warp;
  weather::DomeSubgrid subgrid;
  weather::RingLayout layout = weather::dome_ring_layout();
  glm::dvec3 camera_field{0.0};  // the local frame's origin in the field frame (m)
  weather::DomeRings rings;
  weather::DomeTopSampler sampler;
  Domes(const ReferenceLayer& L, const CloudField& field, int li, const glm::dvec3& camera)
      : placement(weather::dome_placement_params(L.coverage), weather::kDomeShellRadius_m, L.dome_seed),
        warp(L.dome_seed),
        subgrid(L.dome_seed),
        camera_field(camera),
        rings(weather::dome_rings_for(layout, camera)),
        sampler(placement, warp, subgrid, layout,
                [&field, li](const glm::dvec3& x) { return field.coverage_at_field_point(li, x); }) {}
};

CloudField::CloudField(const ReferenceScene& scene, const ReferenceInputs& inputs, bool honour_stratiform,
                       bool cumulus_domes, bool noise_tiling)
    : scene_(scene), inputs_(inputs), honour_stratiform_(honour_stratiform), noise_tiling_(noise_tiling),
      centre_to_camera_ecef_(scene.shell.enu_to_ecef[2] * (scene.shell.radius_m + scene.shell.camera_alt_m)) {
  domes_.resize(scene.layers.size());
  if (!cumulus_domes) return;
  for (std::size_t i = 0; i < scene.layers.size(); ++i) {
    const ReferenceLayer& L = scene.layers[i];
    if (!weather::uses_domes(L.type)) continue;
    // field position of the local origin: W (E 0 + centre_to_camera), W = field_from_local E^T
    const glm::dvec3 camera = L.field_from_local * (glm::transpose(scene.shell.enu_to_ecef) * centre_to_camera_ecef_);
    domes_[i] = std::make_unique<Domes>(L, *this, static_cast<int>(i), camera);
  }
}

CloudField::~CloudField() = default;

double CloudField::coverage_at_field_point(int li, const glm::dvec3& x) const {
  const ReferenceLayer& L = scene_.layers[static_cast<std::size_t>(li)];
  // ECEF direction: W^T x, W = field_from_local E^T
  const glm::dvec3 q = scene_.shell.enu_to_ecef * (glm::transpose(L.field_from_local) * x);
  const double lat = std::atan2(q.z, std::sqrt(q.x * q.x + q.y * q.y)), lon = std::atan2(q.y, q.x);
  return weather::local_coverage(L.coverage, sample_weather_map(inputs_.weather_map, inputs_.pole_south, inputs_.pole_north, lat, lon).r);
}

double CloudField::dome_fraction(int li, const glm::dvec3& p, double alt, double coverage, double ceiling_m,
                                 double shape) const {
  const ReferenceLayer& L = scene_.layers[static_cast<std::size_t>(li)];
  const Domes& D = *domes_[static_cast<std::size_t>(li)];
  const double h = alt - L.base_m;
  if (h >= ceiling_m + weather::kDomeCauliflower_m) return 0.0;
  const glm::dvec3 x = D.camera_field + L.field_from_local * p;
  const glm::dvec3 shell = weather::kDomeShellRadius_m * glm::normalize(x);
  const double unit_top = D.sampler.top_m(D.rings, shell, coverage);
  if (unit_top <= 0.0) return 0.0;
  return weather::dome_fraction(unit_top, ceiling_m, h,
                                shape - interpolate_quantile(inputs_.base_quantiles, 0.5));
}

glm::dvec4 CloudField::weather_at(const glm::dvec3& p) const {
  // Direction from the shell centre in ECEF axes: E (p + (0, 0, R + h)) = E p + (R + h) up_camera.
  const glm::dvec3 q = scene_.shell.enu_to_ecef * p + centre_to_camera_ecef_;
  const double lat = std::atan2(q.z, std::sqrt(q.x * q.x + q.y * q.y));  // |q| ~ 6.4e6 m: no overflow
  const double lon = std::atan2(q.y, q.x);
  return sample_weather_map(inputs_.weather_map, inputs_.pole_south, inputs_.pole_north, lat, lon);
}

double CloudField::height_profile(const ReferenceLayer& l, double x) {
  const double bottom = smoothstep(0.0, std::max(l.bottom_ramp, 1e-3), x);
  const double top = 1.0 - smoothstep(1.0 - std::max(l.top_ramp, 1e-3), 1.0, x);
  return bottom * top * (1.0 + (x - 1.0) * l.top_weight);  // mix(1, x, top_weight)
}

double CloudField::anvil_weight(const ReferenceLayer& l, double f) {
  if (!(l.anvil.spread > 0.0f)) return 0.0;
  const double base = l.anvil.base, top = l.anvil.top, r = 0.2 * (top - base);
  return smoothstep(base, base + r, f) * (1.0 - smoothstep(top - r, top, f));
}

double CloudField::anvil_weight_max(const ReferenceLayer& l, double f0, double f1) {
  return anvil_weight(l, std::clamp(0.5 * (static_cast<double>(l.anvil.base) + l.anvil.top), f0, f1));
}

double CloudField::anvil_coverage(const ReferenceLayer& l, double c, double w) {
  return 1.0 - std::pow(1.0 - c, 1.0 + static_cast<double>(l.anvil.spread) * w);
}

double CloudField::base_shape(const ReferenceLayer& L, const glm::dvec3& field) const {
  if (!noise_tiling_) return sample_r8_trilinear_repeat(inputs_.base_noise, field / L.base_period_m);
  const auto sample = [&](const glm::dvec3& u) { return sample_r8_trilinear_repeat(inputs_.base_noise, u); };
  return weather::tiled_noise(sample, field / L.base_period_m, weather::base_tiling_seed(inputs_.noise_seed, L.type),
                              inputs_.base_mean);
}

double CloudField::detail_shape(const ReferenceLayer& L, const glm::dvec3& field) const {
  if (!noise_tiling_) return sample_r8_trilinear_repeat(inputs_.detail_noise, field / L.detail_period_m);
  const auto sample = [&](const glm::dvec3& u) { return sample_r8_trilinear_repeat(inputs_.detail_noise, u); };
  return weather::tiled_noise(sample, field / L.detail_period_m, weather::detail_tiling_seed(inputs_.noise_seed, L.type),
                              inputs_.detail_mean);
}

glm::dvec3 CloudField::field_point(const ReferenceLayer& L, const glm::dvec3& p, double alt) const {
  const glm::dvec3 stretched =
      L.noise_vertical_scale == 1.0 ? p : p + (L.noise_vertical_scale - 1.0) * alt * scene_.shell.up_at(p);
  return L.noise_shaping * (L.camera_field + L.field_from_local * stretched);
}

double CloudField::depth_fraction(const ReferenceLayer& L, const glm::dvec4& w) const {
  return (honour_stratiform_ && L.stratiform) ? 1.0 : std::clamp(0.5 + w.g, 0.3, 1.0);
}

double CloudField::base_lift(const ReferenceLayer& L, double detail_value) const {
  return L.base_relief * saturate(weather::kBaseLiftMean + detail_value - inputs_.detail_mean);
}

double CloudField::base_lift_factor(const ReferenceLayer& L, double f, double lift) {
  return L.base_relief > 0.0 ? smoothstep(lift, lift + std::max(L.bottom_ramp, 1e-3), f) : 1.0;
}

double CloudField::nominal_base_m(const ReferenceLayer& L) {
  return L.base_m + L.base_relief * weather::kBaseLiftMean * (L.top_m - L.base_m);
}

double CloudField::threshold_fraction(const ReferenceLayer& L, double f, double profile, double coverage, double q,
                                      double shape, double& anvil_factor) const {
  double d = saturate((shape * profile - q) / kCoverageEdge);
  anvil_factor = 1.0;
  if (const double w_anvil = anvil_weight(L, f); w_anvil > 0.0) {
    const double shield_threshold = interpolate_quantile(inputs_.base_quantiles, 1.0 - anvil_coverage(L, coverage, w_anvil));
    const double d_shield = saturate((shape * profile - shield_threshold) / kCoverageEdge);
    anvil_factor = 1.0 - w_anvil * (1.0 - static_cast<double>(L.anvil.density_ratio)) * (1.0 - d);
    d = std::max(d, d_shield);
  }
  return d;
}

double CloudField::extinction_scale(const ReferenceLayer& L, const glm::dvec4& w) {
  return L.density_scale * std::exp2(2.0 * (w.b - 0.5)) * L.sigma_max_per_m;
}

CloudSample CloudField::sample(int li, const glm::dvec3& p, double alt, bool detail, std::uint64_t& evals) const {
  CloudSample out;
  const ReferenceLayer& L = scene_.layers[static_cast<std::size_t>(li)];
  const double f = (alt - L.base_m) / (L.top_m - L.base_m);
  if (!(f > 0.0 && f < 1.0)) return out;
  ++evals;
  const glm::dvec4 w = weather_at(p);
  out.coverage = weather::local_coverage(L.coverage, w.r);
  if (out.coverage <= 0.0) return out;
  const double f_v = depth_fraction(L, w);
  // the detail noise at the sample's field point, read once where first needed (the
  // textured base's lift and the erosion both use it; values lie in [0, 1])
  double detail_value = -1.0;
  const auto detail_at = [&](const glm::dvec3& field) {
    if (detail_value < 0.0) detail_value = detail_shape(L, field);
    return detail_value;
  };
  // steps 5 and 6 of the header for the cloud fraction d > 0
  const auto extinction = [&](double d, double anvil_factor, const glm::dvec3& field) {
    if (detail && d < 1.0) {
      const double floor_value = detail_at(field) * L.erosion;
      d = saturate((d - floor_value) / (1.0 - floor_value));
    }
    return d * anvil_factor * extinction_scale(L, w);
  };
  if (domes_[static_cast<std::size_t>(li)]) {  // the cumulus domes (weather::dome_fraction)
    const glm::dvec3 field = field_point(L, p, alt);
    const double shape = base_shape(L, field);
    const double d = dome_fraction(li, p, alt, out.coverage, f_v * (L.top_m - L.base_m), shape);
    if (d > 0.0) out.sigma_t = extinction(d, 1.0, field);
    return out;
  }
  if (f > f_v) return out;
  const double profile = height_profile(L, f / f_v);
  if (profile <= 0.0) return out;
  const glm::dvec3 field = field_point(L, p, alt);
  const double threshold = interpolate_quantile(inputs_.base_quantiles, 1.0 - out.coverage);
  double anvil_factor = 1.0;
  const double shape = base_shape(L, field);
  double d = threshold_fraction(L, f, profile, out.coverage, threshold, shape, anvil_factor);
  // a textured base (step 3): the fraction over the profile lifted where the detail noise
  // reads D (with detail; its mean without)
  if (d > 0.0 && L.base_relief > 0.0 && f < L.base_relief + L.bottom_ramp) {
    const double lift = base_lift(L, detail ? detail_at(field) : inputs_.detail_mean);
    d = threshold_fraction(L, f, profile * base_lift_factor(L, f, lift), out.coverage, threshold, shape, anvil_factor);
  }
  if (d > 0.0) out.sigma_t = extinction(d, anvil_factor, field);
  return out;
}

double CloudField::saturate_mean(double a, double b) {
  const auto ramp_integral = [](double x) { return x <= 0.0 ? 0.0 : (x < 1.0 ? 0.5 * x * x : x - 0.5); };
  const double d = b - a;
  return std::abs(d) > 1e-6 ? (ramp_integral(b) - ramp_integral(a)) / d : saturate(0.5 * (a + b));
}

int CloudField::column_pieces(const ReferenceLayer& L, double step_m) {
  const int k = model::kColumnPiecesPerStep;
  if (!(L.anvil.spread > 0.0f)) return k;
  const double ramp_m = 0.2 * (static_cast<double>(L.anvil.top) - L.anvil.base) * (L.top_m - L.base_m);  // anvil_weight's
  return std::clamp(static_cast<int>(std::ceil(k * std::abs(step_m) / std::max(ramp_m, 1.0))), k, model::kColumnAnvilPiecesMax);
}

double CloudField::profile_end_m(int li, double f_v) const {
  const ReferenceLayer& L = scene_.layers[static_cast<std::size_t>(li)];
  if (domes_[static_cast<std::size_t>(li)]) return L.top_m;  // cauliflower tops rise above the profile's end
  return L.base_m + (L.top_m - L.base_m) * f_v;
}

double CloudField::profile_top_m(int li, const glm::dvec3& p) const {
  return profile_end_m(li, depth_fraction(scene_.layers[static_cast<std::size_t>(li)], weather_at(p)));
}

glm::dvec2 CloudField::column_depths(int li, const glm::dvec3& p, double alt, const std::function<int(double)>& steps_for,
                                     std::uint64_t& evals) const {
  const ReferenceLayer& L = scene_.layers[static_cast<std::size_t>(li)];
  const glm::dvec4 w = weather_at(p);  // one value: the column is vertical
  const double thickness = L.top_m - L.base_m, f_v = depth_fraction(L, w);
  const double len_below = std::max(alt - L.base_m, 0.0), len_above = std::max(profile_end_m(li, f_v) - alt, 0.0);
  const glm::dvec3 up = scene_.shell.up_at(p);  // along it the altitude is alt + s
  if (domes_[static_cast<std::size_t>(li)]) {  // the domes' fraction is no threshold of S: the full sample at the pieces' midpoints
    const auto part = [&](double len_m) {
      const int m = steps_for(std::abs(len_m)) * model::kColumnPiecesPerStep;
      double tau = 0.0;
      for (int i = 0; i < m && len_m != 0.0; ++i) {
        const double s = (i + 0.5) * len_m / m;
        tau += sample(li, p + up * s, alt + s, false, evals).sigma_t * std::abs(len_m) / m;
      }
      return tau;
    };
    return {part(-len_below), part(len_above)};
  }
  const double coverage = weather::local_coverage(L.coverage, w.r);
  if (coverage <= 0.0) return glm::dvec2(0.0);
  const double q = interpolate_quantile(inputs_.base_quantiles, 1.0 - coverage);
  const bool anvil = L.anvil.spread > 0.0f;
  const auto shape_at = [&](double s) {
    ++evals;
    return base_shape(L, field_point(L, p + up * s, alt + s));
  };
  const auto fraction_at = [&](double s) { return (alt + s - L.base_m) / thickness; };
  // the profile at height fraction f, over the base-shape field's lifted base (a textured
  // base's mean lift)
  const double mean_lift = base_lift(L, inputs_.detail_mean);
  const auto profile_at = [&](double f) {
    return height_profile(L, std::clamp(f / f_v, 0.0, 1.0)) * base_lift_factor(L, f, mean_lift);
  };
  const double shape_p = shape_at(0.0);  // shared by both parts
  const double g_p = (shape_p * profile_at(fraction_at(0.0)) - q) / kCoverageEdge;
  // the part of signed length len_m (> 0 upwards)
  const auto part = [&](double len_m) {
    if (len_m == 0.0) return 0.0;
    const int steps = steps_for(std::abs(len_m));
    const double ds = len_m / steps;
    const int pieces = column_pieces(L, ds);
    double sum = 0.0;  // of the pieces' mean cloud fraction (times the anvil factor)
    double shape0 = shape_p, g0 = g_p;
    for (int j = 0; j < steps; ++j) {
      const double shape1 = shape_at((j + 1) * ds);
      for (int k = 0; k < pieces; ++k) {
        if (anvil) {
          const double u = (k + 0.5) / pieces, f = fraction_at((j + u) * ds);
          if (!(f > 0.0 && f < f_v)) continue;
          double anvil_factor = 1.0;
          const double d = threshold_fraction(L, f, profile_at(f), coverage, q,
                                              shape0 + (shape1 - shape0) * u, anvil_factor);
          sum += d * anvil_factor;
        } else {
          const double u = static_cast<double>(k + 1) / pieces;
          const double g1 = ((shape0 + (shape1 - shape0) * u) * profile_at(fraction_at((j + u) * ds)) - q) / kCoverageEdge;
          sum += saturate_mean(g0, g1);
          g0 = g1;
        }
      }
      shape0 = shape1;
    }
    return sum * std::abs(ds) / pieces;
  };
  return extinction_scale(L, w) * glm::dvec2(part(-len_below), part(len_above));
}

}  // namespace cloudsvc::reference
