// View geometry, sun and per-layer parameters of the reference (see reference_scene.h).
#include "renderer/reference/reference_scene.h"

#include "weather/cumulus_domes.h"
#include "weather/noise_shaping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geodesy/solar_position.h"
#include "renderer/model/atmosphere_constants.h"
#include "renderer/model/droplet_optics.h"
#include "renderer/model/scene_constants.h"

namespace cloudsvc::reference {

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
}  // namespace

glm::dmat3 field_rotation(const weather::Wind& wind, const WindAnchor& anchor, double unix_time_s) {
  const glm::dvec3 P = geo::geodetic_to_ecef(anchor.position);
  const glm::dmat3 E = geo::enu_to_ecef(anchor.position.lat_deg, anchor.position.lon_deg);
  const glm::dvec3 v = E[0] * wind.east_mps + E[1] * wind.north_mps;  // m/s, ECEF axes
  const glm::dvec3 axis = glm::cross(P, v);
  const double axis_len = glm::length(axis), speed = glm::length(v), radius = glm::length(P);
  if (!(speed > 0.0) || !(radius > 0.0) || !(axis_len > 0.0)) return glm::dmat3(1.0);
  const glm::dvec3 k = axis / axis_len;
  const double omega = speed / radius;  // rad/s
  const double angle = std::remainder(omega * (unix_time_s - anchor.unix_time_s), 2.0 * std::numbers::pi);
  // Rodrigues: rotation by theta about k applied to x is
  //   x cos(theta) + (k x x) sin(theta) + k (k . x)(1 - cos(theta)); here theta = -angle.
  const double c = std::cos(-angle), s = std::sin(-angle);
  glm::dmat3 R(1.0);
  for (int col = 0; col < 3; ++col) {
    glm::dvec3 e(0.0);
    e[col] = 1.0;
    R[col] = e * c + glm::cross(k, e) * s + k * (glm::dot(k, e) * (1.0 - c));
  }
  return R;
}

glm::dvec3 ReferenceCamera::ray_at(double px, double py) const {
  const double ndc_x = px / width * 2.0 - 1.0;
  const double ndc_y = 1.0 - py / height * 2.0;  // row 0 is the top
  return glm::normalize(forward + (window.center_x + ndc_x * window.half_x) * right +
                        (window.center_y + ndc_y * window.half_y) * up);
}

double ShellFrame::altitude_of(const glm::dvec3& p) const {
  return glm::length(p + glm::dvec3(0.0, 0.0, radius_m + camera_alt_m)) - radius_m;
}

glm::dvec3 ShellFrame::up_at(const glm::dvec3& p) const {
  return glm::normalize(p + glm::dvec3(0.0, 0.0, radius_m + camera_alt_m));
}

ReferenceScene make_reference_scene(const ViewRequest& view, const weather::Weather& weather,
                                    const WindAnchor* anchor, model::CloudPhaseModel phase) {
  ReferenceScene s;
  const geo::Geodetic& pos = view.position;

  // Camera: body axes from heading/pitch/roll (aviation 3-2-1 sequence) in ENU.
  const geo::BodyAxes axes = geo::body_axes_enu(view.attitude);
  s.camera.forward = axes.forward;
  s.camera.right = axes.right;
  s.camera.up = axes.up;
  s.camera.width = view.width;
  s.camera.height = view.height;
  s.camera.window = image_window(view);
  s.camera.near_m = view.near_m;
  s.camera.far_m = view.far_m;

  // Shell: osculating sphere of the WGS84 ellipsoid at the camera (radius sqrt(M N)).
  s.shell.radius_m = geo::gaussian_radius(pos.lat_deg);
  s.shell.camera_alt_m = pos.alt_m;
  s.shell.ground_alt_m = std::min(0.0, pos.alt_m - 1.0);
  s.shell.enu_to_ecef = geo::enu_to_ecef(pos.lat_deg, pos.lon_deg);
  s.shell.camera_ecef = geo::geodetic_to_ecef(pos);

  // Sun: azimuth clockwise from north, geometric elevation -> ENU unit vector.
  const geo::SolarPosition sp = geo::solar_position(view.unix_time_s, pos.lat_deg, pos.lon_deg);
  s.sun_elevation_deg = sp.elevation_deg;
  s.sun_azimuth_deg = sp.azimuth_deg;
  const double el = sp.elevation_deg * kDegToRad, az = sp.azimuth_deg * kDegToRad;
  s.sun_local = glm::dvec3(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
  s.ground_albedo = model::ground_albedo_rgb(weather.ground_albedo);
  s.aerosol_scale = model::atmosphere::aerosol_scale_of(weather.visibility_m);

  const WindAnchor here{pos, view.unix_time_s};
  const WindAnchor& a = anchor ? *anchor : here;
  const std::size_t n = std::min<std::size_t>(weather.layers.size(), weather::kMaxCloudLayers);
  for (std::size_t i = 0; i < n; ++i) {
    const weather::CloudLayer& l = weather.layers[i];
    const weather::CloudTypeTraits& tr = weather::cloud_type_traits(l.type);
    ReferenceLayer r;
    r.base_m = l.base_m;
    r.top_m = l.top_m;
    r.coverage = l.coverage;
    r.density_scale = l.density_scale;
    r.sigma_max_per_m = model::cloud_extinction_per_m(l.droplet_diameter_um);
    r.phase = model::jdd_params(l.droplet_diameter_um);
    if (phase == model::CloudPhaseModel::kMie) r.mie_phase = model::mie_phase_table(l.droplet_diameter_um);
    r.base_period_m = tr.noise_scale_m;
    r.detail_period_m = tr.noise_scale_m / 8.0;
    r.erosion = tr.profile.base_erosion;
    r.bottom_ramp = tr.profile.bottom_ramp;
    r.top_ramp = tr.profile.top_ramp;
    r.top_weight = tr.profile.top_weight;
    r.noise_vertical_scale = tr.noise_vertical_scale;
    r.stratiform = tr.stratiform;
    r.base_relief = tr.base_relief;
    r.anvil = tr.anvil;
    r.type = l.type;
    r.dome_seed = weather::dome_placement_seed(weather, i);
    const glm::dmat3 rot = field_rotation(l.wind, a, view.unix_time_s);
    r.field_from_local = rot * s.shell.enu_to_ecef;
    r.camera_field = rot * s.shell.camera_ecef;
    r.noise_shaping = weather::noise_shaping(tr);
    s.layers.push_back(r);
  }
  return s;
}

}  // namespace cloudsvc::reference
