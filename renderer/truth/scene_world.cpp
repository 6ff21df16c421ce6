// The cloud scene as a TruthWorld (see scene_world.h).
#include "renderer/truth/scene_world.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/model/scene_constants.h"
#include "renderer/reference/atmosphere_monte_carlo.h"  // the air's majorant band edges
#include "renderer/reference/reference_atmosphere.h"

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
  if (!in.base_noise.data.empty())
    m.base_noise = *std::max_element(in.base_noise.data.begin(), in.base_noise.data.end()) / 255.0;
  m.base_quantiles = in.base_quantiles;
  return m;
}

SceneMedium::SceneMedium(const reference::ReferenceScene& scene, const reference::CloudField& field)
    : scene_(scene), field_(field), centre_to_camera_(0.0, 0.0, scene.shell.radius_m + scene.shell.camera_alt_m) {}

void SceneMedium::at(const glm::dvec3& x, double altitude_m, MediumPoint& out) const {
  const reference::atmo::Medium air = reference::atmo::medium_at(altitude_m);
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
  const double c = L.coverage;
  const double c_max = std::clamp(c + 1.2 * std::min(c, 1.0 - c) * (2.0 * maxima.map_coverage - 1.0), 0.0, 1.0);
  if (c_max <= 0.0) return 0.0;
  const double f0 = (a0 - L.base_m) / (L.top_m - L.base_m), f1 = (a1 - L.base_m) / (L.top_m - L.base_m);
  // x = f / f_v with the depth fraction f_v in [0.3, 1] (1 for a stratiform layer honoured as such)
  const double fv_min = (honour_stratiform && L.stratiform) ? 1.0 : 0.3;
  const double profile = profile_bound(L, f0, f1 / fv_min);
  const double threshold = reference::interpolate_quantile(maxima.base_quantiles, 1.0 - c_max);
  const double d = std::clamp((maxima.base_noise * profile - threshold) / reference::kCoverageEdge, 0.0, 1.0);
  return d * L.density_scale * std::exp2(2.0 * (maxima.map_density - 0.5)) * L.sigma_max_per_m;
}

TruthWorld make_scene_world(const reference::ReferenceScene& scene, const reference::ReferenceInputs& inputs,
                            bool honour_stratiform, const SceneMedium& medium) {
  TruthWorld w;
  const reference::ShellFrame& s = scene.shell;
  w.radius_m = s.radius_m;
  w.ground_alt_m = s.ground_alt_m;
  w.top_alt_m = reference::atmo::kThickness;
  // Band edges: the air's bands, every cloud layer's sub-bands, the ground and the top.
  std::vector<double>& e = w.band_edges;
  e.push_back(w.ground_alt_m);
  e.push_back(w.top_alt_m);
  for (int b = 1; b < reference::mc::majorant_band_count(); ++b) e.push_back(reference::mc::majorant_band_bottom(b));
  for (const reference::ReferenceLayer& L : scene.layers)
    for (int k = 0; k <= kCloudSubBands; ++k) e.push_back(L.base_m + (L.top_m - L.base_m) * k / kCloudSubBands);
  std::sort(e.begin(), e.end());
  e.erase(std::remove_if(e.begin(), e.end(), [&](double a) { return a < w.ground_alt_m || a > w.top_alt_m; }), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  const FieldMaxima maxima = field_maxima(inputs);
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    const glm::dvec3 air = reference::atmo::max_extinction(e[i], e[i + 1]);
    double cloud = 0.0;
    for (const reference::ReferenceLayer& L : scene.layers)
      cloud += cloud_extinction_bound(L, maxima, honour_stratiform, e[i], e[i + 1]);
    const double air_bound = std::max({air.r, air.g, air.b}) * (1.0 + 1e-9);
    w.band_air_majorant.push_back(air_bound);
    w.band_majorant.push_back(air_bound + cloud * (1.0 + 1e-9));
  }

  w.sun = scene.sun_local;
  w.sun_irradiance = glm::dvec3(model::kSolarIrradiance[0], model::kSolarIrradiance[1], model::kSolarIrradiance[2]);
  w.sun_angular_radius_rad = model::kSunAngularRadiusDeg * std::numbers::pi / 180.0;
  w.ground_albedo = reference::atmo::kGroundAlbedo;
  w.sky_radiance = glm::dvec3(model::kNightSkyRadiance);
  w.aerosol_g = reference::atmo::kMieG;
  for (std::size_t li = 0; li < scene.layers.size() && li < w.cloud_phase.size(); ++li)
    w.cloud_phase[li] = scene.layers[li].phase;
  w.medium = &medium;
  return w;
}

}  // namespace cloudsvc::truth
