// The cloud scene as a TruthWorld (see scene_world.h).
#include "renderer/truth/scene_world.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/model/scene_constants.h"
#include "renderer/reference/atmosphere_monte_carlo.h"  // the air's majorant band edges
#include "renderer/reference/reference_atmosphere.h"
#include "weather/noise_tiling.h"
#include "weather/weather_map.h"

namespace cloudsvc::truth {

namespace {

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Largest of CloudField::height_profile over x in [x0, x1] within [0, 1]: the bottom
// ramp increases, the top ramp decreases and the top weight's factor is linear, so each
// is bounded at an end of the interval.
double profile_bound(const reference::ReferenceLayer& L, double x0, double x1) {
  x0 = std::clamp(x0, 0.0, 1.0);
  x1 = std::clamp(x1, 0.0, 1.0);
  const double bottom = smoothstep(0.0, std::max(L.bottom_ramp, 1e-3), x1);
  const double top = 1.0 - smoothstep(1.0 - std::max(L.top_ramp, 1e-3), 1.0, x0);
  const double weight = std::max(1.0 + (x0 - 1.0) * L.top_weight, 1.0 + (x1 - 1.0) * L.top_weight);
  return bottom * top * std::max(weight, 0.0);
}

}  // namespace

FieldMaxima field_maxima(const reference::ReferenceInputs& in) {
  FieldMaxima m;
  m.map_coverage = std::max(in.pole_south.r, in.pole_north.r);
  m.map_density = std::max(in.pole_south.b, in.pole_north.b);
  const std::vector<float>& t = in.weather_map.rgba;
  for (std::size_t i = 0; i + 3 < t.size(); i += 4) {
    m.map_coverage = std::max(m.map_coverage, static_cast<double>(t[i]));
    m.map_density = std::max(m.map_density, static_cast<double>(t[i + 2]));
  }
  if (t.empty()) m.map_coverage = m.map_density = 1.0;  // no map: any value
  m.base_noise = 1.0;  // the volume's largest texel is 1 (stretched), and the tiled noise may reach 1
  m.base_quantiles = in.base_quantiles;
  return m;
}

SceneMedium::SceneMedium(const reference::ReferenceScene& scene, const reference::CloudField& field)
    : scene_(scene), field_(field), centre_to_camera_(0.0, 0.0, scene.shell.radius_m + scene.shell.camera_alt_m) {}

void SceneMedium::at(const glm::dvec3& x, double altitude_m, MediumPoint& out) const {
  const reference::atmo::Medium air = reference::atmo::medium_at(altitude_m, scene_.aerosol_scale);
  out.rayleigh = air.rayleigh_scattering;
  out.aerosol = air.mie_scattering;
  out.absorption = air.extinction - air.rayleigh_scattering - glm::dvec3(air.mie_scattering);
  const glm::dvec3 p = x - centre_to_camera_;  // the reference's local frame
  std::uint64_t evals = 0;
  for (std::size_t li = 0; li < scene_.layers.size(); ++li) {
    const reference::ReferenceLayer& L = scene_.layers[li];
    if (altitude_m <= L.base_m || altitude_m >= L.top_m) continue;
    out.cloud[li] = field_.sample(static_cast<int>(li), p, altitude_m, true, evals).sigma_t;
  }
}

double cloud_extinction_bound(const reference::ReferenceLayer& L, const FieldMaxima& maxima, bool honour_stratiform,
                              double a0, double a1) {
  if (a1 <= L.base_m || a0 >= L.top_m) return 0.0;
  const double c_max = weather::local_coverage(L.coverage, maxima.map_coverage);
  if (c_max <= 0.0) return 0.0;
  const double f0 = (a0 - L.base_m) / (L.top_m - L.base_m), f1 = (a1 - L.base_m) / (L.top_m - L.base_m);
  // x = f / f_v with the depth fraction f_v in [0.3, 1] (1 for a stratiform layer honoured as such)
  const double fv_min = (honour_stratiform && L.stratiform) ? 1.0 : 0.3;
  const double profile = profile_bound(L, f0, f1 / fv_min);
  // an anvil widens the coverage (its factor a <= 1 only thins the shield)
  const double c_bound = reference::CloudField::anvil_coverage(L, c_max, reference::CloudField::anvil_weight_max(L, f0, f1));
  const double threshold = reference::interpolate_quantile(maxima.base_quantiles, 1.0 - c_bound);
  const double d = std::clamp((maxima.base_noise * profile - threshold) / reference::kCoverageEdge, 0.0, 1.0);
  return d * L.density_scale * std::exp2(2.0 * (maxima.map_density - 0.5)) * L.sigma_max_per_m;
}

std::vector<double> scene_band_edges(const reference::ReferenceScene& scene) {
  const double ground = scene.shell.ground_alt_m, top = reference::atmo::kThickness;
  std::vector<double> e = {ground, top};
  for (int b = 1; b < reference::mc::majorant_band_count(); ++b) e.push_back(reference::mc::majorant_band_bottom(b));
  for (const reference::ReferenceLayer& L : scene.layers)
    for (int k = 0; k <= kCloudSubBands; ++k) e.push_back(L.base_m + (L.top_m - L.base_m) * k / kCloudSubBands);
  std::sort(e.begin(), e.end());
  e.erase(std::remove_if(e.begin(), e.end(), [&](double a) { return a < ground || a > top; }), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

SceneLocalMajorant::SceneLocalMajorant(const reference::ReferenceScene& scene,
                                       const reference::ReferenceInputs& inputs, bool honour_stratiform,
                                       const std::vector<double>& band_edges, bool noise_tiling)
    : scene_(scene), inputs_(inputs), edges_(band_edges), noise_tiling_(noise_tiling) {
  for (std::size_t i = 0; i + 1 < edges_.size(); ++i) {
    std::vector<double> row, anvil_row;
    for (const reference::ReferenceLayer& L : scene.layers) {
      const double f0 = (edges_[i] - L.base_m) / (L.top_m - L.base_m), f1 = (edges_[i + 1] - L.base_m) / (L.top_m - L.base_m);
      const double fv_min = (honour_stratiform && L.stratiform) ? 1.0 : 0.3;
      row.push_back(edges_[i + 1] <= L.base_m || edges_[i] >= L.top_m ? 0.0 : profile_bound(L, f0, f1 / fv_min));
      anvil_row.push_back(reference::CloudField::anvil_weight_max(L, f0, f1));
    }
    profile_.push_back(std::move(row));
    anvil_.push_back(std::move(anvil_row));
  }
  if (!inputs.base_noise.data.empty()) base_ = weather::NoiseMaxPyramid(inputs.base_noise);
  const weather::WeatherMap& map = inputs.weather_map;
  polar_[0] = glm::dvec2(inputs.pole_south.r, inputs.pole_south.b);
  polar_[1] = glm::dvec2(inputs.pole_north.r, inputs.pole_north.b);
  for (int j = 0; j < std::min(4, map.height); ++j)
    for (int i = 0; i < map.width; ++i)
      for (int pole = 0; pole < 2; ++pole) {
        const int row = pole == 0 ? j : map.height - 1 - j;
        const float* t = &map.rgba[(static_cast<std::size_t>(row) * map.width + i) * 4];
        polar_[pole] = glm::max(polar_[pole], glm::dvec2(t[0], t[2]));
      }
}

glm::dvec2 SceneLocalMajorant::map_maxima(const glm::dvec3& a, const glm::dvec3& b) const {
  const weather::WeatherMap& map = inputs_.weather_map;
  if (map.rgba.empty()) return glm::dvec2(1.0);
  const double W = map.width, H = map.height;
  double x[2], y[2];
  const glm::dvec3 ends[2] = {a, b};
  for (int k = 0; k < 2; ++k) {
    const glm::dvec3 q = scene_.shell.enu_to_ecef * ends[k];  // from the shell centre, ECEF axes
    const double lat = std::atan2(q.z, std::sqrt(q.x * q.x + q.y * q.y));
    const double lon = std::atan2(q.y, q.x);
    x[k] = (lon / (2.0 * std::numbers::pi) + 0.5) * W - 0.5;
    y[k] = (lat / std::numbers::pi + 0.5) * H - 0.5;
  }
  const double y_lo = std::min(y[0], y[1]), y_hi = std::max(y[0], y[1]);
  if (y_lo < 2.0) return polar_[0];  // near the south pole: any longitude, the pole blend
  if (y_hi > H - 3.0) return polar_[1];
  if (std::abs(x[0] - x[1]) > 0.5 * W) (x[0] < x[1] ? x[0] : x[1]) += W;  // across the antimeridian
  const int i0 = static_cast<int>(std::floor(std::min(x[0], x[1]))) - 1, i1 = static_cast<int>(std::floor(std::max(x[0], x[1]))) + 2;
  const int j0 = std::max(0, static_cast<int>(std::floor(y_lo)) - 1);
  const int j1 = std::min(map.height - 1, static_cast<int>(std::floor(y_hi)) + 2);
  glm::dvec2 m(0.0);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const int iw = ((i % map.width) + map.width) % map.width;
      const float* t = &map.rgba[(static_cast<std::size_t>(j) * map.width + iw) * 4];
      m = glm::max(m, glm::dvec2(t[0], t[2]));
    }
  return m;
}

double SceneLocalMajorant::cloud_bound(int band, const glm::dvec3& a, const glm::dvec3& b) const {
  const std::vector<double>& prof = profile_[static_cast<std::size_t>(band)];
  const double R = scene_.shell.radius_m;
  const glm::dvec3 to_local(0.0, 0.0, R + scene_.shell.camera_alt_m);
  const double band_height = edges_[static_cast<std::size_t>(band) + 1] - edges_[static_cast<std::size_t>(band)];
  const double band_top = edges_[static_cast<std::size_t>(band) + 1];
  const double length = glm::length(b - a);
  glm::dvec2 map_max(-1.0);
  double bound = 0.0;
  for (std::size_t li = 0; li < scene_.layers.size(); ++li) {
    if (prof[li] <= 0.0) continue;
    const reference::ReferenceLayer& L = scene_.layers[li];
    if (map_max.x < 0.0) map_max = map_maxima(a, b);
    const double c_max = weather::local_coverage(L.coverage, map_max.x);
    if (c_max <= 0.0) continue;
    // Noise-space box of the stretch (m), then texture units: CloudField::field_point of its
    // ends (linear but for the vertical stretch, whose deviation `widen` bounds in the field
    // frame and the strands' S, weather/noise_shaping.h, scales by at most its row sums).
    glm::dvec3 f[2];
    const glm::dvec3 ends[2] = {a, b};
    for (int k = 0; k < 2; ++k) {
      const double r = glm::length(ends[k]);
      const glm::dvec3 p = ends[k] - to_local;
      f[k] = L.noise_shaping *
             (L.camera_field + L.field_from_local * (p + (L.noise_vertical_scale - 1.0) * (r - R) * (ends[k] / r)));
    }
    const double widen_field = std::abs(L.noise_vertical_scale - 1.0) * (band_height + band_top * length / R + 1.0);
    glm::dvec3 widen(0.0);
    const glm::dmat3& S = L.noise_shaping;
    for (int i = 0; i < 3; ++i)  // row i of S (glm is column-major)
      widen[i] = widen_field * (std::abs(S[0][i]) + std::abs(S[1][i]) + std::abs(S[2][i]));
    const glm::dvec3 lo = (glm::min(f[0], f[1]) - widen) / L.base_period_m;
    const glm::dvec3 hi = (glm::max(f[0], f[1]) + widen) / L.base_period_m;
    const double noise = noise_tiling_ ? weather::tiled_max_over(base_, lo, hi,
                                                                 weather::base_tiling_seed(inputs_.noise_seed, L.type),
                                                                 inputs_.base_mean)
                                       : base_.max_over(lo, hi);
    const double c_bound = reference::CloudField::anvil_coverage(L, c_max, anvil_[static_cast<std::size_t>(band)][li]);
    const double threshold = reference::interpolate_quantile(inputs_.base_quantiles, 1.0 - c_bound);
    const double d = std::clamp((noise * prof[li] - threshold) / reference::kCoverageEdge, 0.0, 1.0);
    bound += d * L.density_scale * std::exp2(2.0 * (map_max.y - 0.5)) * L.sigma_max_per_m;
  }
  return bound * (1.0 + 1e-9);
}

TruthWorld make_scene_world(const reference::ReferenceScene& scene, const reference::ReferenceInputs& inputs,
                            bool honour_stratiform, const SceneMedium& medium, const SceneLocalMajorant* local) {
  TruthWorld w;
  const reference::ShellFrame& s = scene.shell;
  w.radius_m = s.radius_m;
  w.ground_alt_m = s.ground_alt_m;
  w.top_alt_m = reference::atmo::kThickness;
  w.band_edges = scene_band_edges(scene);
  const std::vector<double>& e = w.band_edges;
  const FieldMaxima maxima = field_maxima(inputs);
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    const glm::dvec3 air = reference::atmo::max_extinction(e[i], e[i + 1], scene.aerosol_scale);
    double cloud = 0.0;
    for (const reference::ReferenceLayer& L : scene.layers)
      cloud += cloud_extinction_bound(L, maxima, honour_stratiform, e[i], e[i + 1]);
    const double air_bound = std::max({air.r, air.g, air.b}) * (1.0 + 1e-9);
    w.band_air_majorant.push_back(air_bound);
    w.band_majorant.push_back(air_bound + cloud * (1.0 + 1e-9));
    w.band_local.push_back(cloud > 0.0 ? 1 : 0);
  }
  if (local) {
    w.local = local;
    w.local_stretch_m = 1e9;
    for (const reference::ReferenceLayer& L : scene.layers) {  // four base-noise texels of the finest layer
      // (in metres along the direction the strands' S makes finest: its largest column norm)
      double stretch = 1.0;
      for (int j = 0; j < 3; ++j) stretch = std::max(stretch, glm::length(L.noise_shaping[j]));
      w.local_stretch_m =
          std::min(w.local_stretch_m, 4.0 * L.base_period_m / stretch / std::max(1, inputs.base_noise.size));
    }
  }

  w.sun = scene.sun_local;
  w.sun_irradiance = glm::dvec3(model::kSolarIrradiance[0], model::kSolarIrradiance[1], model::kSolarIrradiance[2]);
  w.sun_angular_radius_rad = model::kSunAngularRadiusDeg * std::numbers::pi / 180.0;
  w.ground_albedo = scene.ground_albedo;
  w.sky_radiance = glm::dvec3(model::kNightSkyRadiance);
  w.aerosol_g = reference::atmo::kMieG;
  for (std::size_t li = 0; li < scene.layers.size() && li < w.cloud_phase.size(); ++li) {
    w.cloud_phase[li] = scene.layers[li].phase;
    w.cloud_mie[li] = scene.layers[li].mie_phase.get();  // the scene outlives the world
  }
  w.medium = &medium;
  return w;
}

}  // namespace cloudsvc::truth
