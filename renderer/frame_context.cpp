#include "renderer/frame_context.h"

#include "renderer/model/atmosphere_constants.h"
#include "renderer/model/scene_constants.h"
#include "weather/noise_shaping.h"

#include <algorithm>
#include <cmath>

namespace cloudsvc {

namespace {
constexpr double kDegToRad = M_PI / 180.0;
// Highest point the march reach must see over the horizon even without a layer that high.
constexpr double kMinReachAltitudeM = 12000.0;
}  // namespace

double horizon_reach_m(double R, double h, double H) {
  return std::sqrt(std::max(h, 0.0) * (2.0 * R + std::max(h, 0.0))) + std::sqrt(std::max(H, 0.0) * (2.0 * R + H));
}

unsigned FrameContext::culled_mask() const {
  unsigned mask = 0;
  for (int i = 0; i < layer_count; ++i)
    if (layers[static_cast<size_t>(i)].culled) mask |= 1u << i;
  return mask;
}

FrameContext make_frame_context(const ViewRequest& view, const weather::Weather& weather, const WindAnchor& anchor) {
  FrameContext c;
  c.view = view;
  const geo::Geodetic& pos = view.position;
  c.camera_ecef = geo::geodetic_to_ecef(pos);
  c.enu_to_ecef = geo::enu_to_ecef(pos.lat_deg, pos.lon_deg);
  c.axes = geo::body_axes_enu(view.attitude);
  c.window = image_window(view);

  // Shell: osculating sphere at the camera. Ground at altitude 0, or just below a camera
  // that is below the ellipsoid (no terrain or geoid model).
  c.shell_radius_m = geo::gaussian_radius(pos.lat_deg);
  c.camera_altitude_m = pos.alt_m;
  c.ground_altitude_m = std::min(0.0, pos.alt_m - 1.0);
  double highest = kMinReachAltitudeM;
  for (const auto& l : weather.layers) highest = std::max(highest, l.top_m);
  c.march_reach_m = horizon_reach_m(c.shell_radius_m, pos.alt_m - c.ground_altitude_m, highest);

  c.sun = geo::solar_position(view.unix_time_s, pos.lat_deg, pos.lon_deg);
  const double el = c.sun.elevation_deg * kDegToRad, az = c.sun.azimuth_deg * kDegToRad;
  c.sun_enu = glm::dvec3(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
  c.sun_ecef = glm::normalize(c.enu_to_ecef * c.sun_enu);

  c.ground_albedo = model::ground_albedo_rgb(weather.ground_albedo);
  c.aerosol_scale = model::atmosphere::aerosol_scale_of(weather.visibility_m);
  c.layer_count = std::min<int>(static_cast<int>(weather.layers.size()), gpu::kMaxLayers);
  const glm::dvec3 cam_normal = c.enu_to_ecef[2];
  for (int i = 0; i < c.layer_count; ++i) {
    LayerFrame& lf = c.layers[static_cast<size_t>(i)];
    lf.layer = weather.layers[static_cast<size_t>(i)];
    const weather::CloudTypeTraits& tr = weather::cloud_type_traits(lf.layer.type);
    lf.base_period_m = tr.noise_scale_m;
    lf.detail_period_m = tr.noise_scale_m / 8.0;
    // Wind: the field is sampled at rot * x (weather/wind_drift.h).
    lf.field_rotation = wind_rotation(lf.layer.wind, anchor, view.unix_time_s);
    // Noise space: world positions with altitude scaled by k along the ellipsoid normal,
    // a fixed map of the world (no camera dependence); here the camera's point of it.
    lf.noise_shaping = weather::noise_shaping(tr);
    lf.camera_field_m =
        lf.noise_shaping * (lf.field_rotation * (c.camera_ecef + (tr.noise_vertical_scale - 1.0) * pos.alt_m * cam_normal));
  }
  // The aerial-perspective volume starts as the symmetric frustum around the camera's
  // (plan_view_dependent widens or keeps it).
  c.ap = ApFrustum{c.axes.forward, c.axes.right, c.axes.up, c.window.bound_x(), c.window.bound_y()};
  return c;
}

}  // namespace cloudsvc
