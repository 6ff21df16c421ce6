#include "renderer/scene_setup.h"

#include <algorithm>
#include <cmath>

#include "geodesy/solar_position.h"
#include "renderer/model/droplet_optics.h"
#include "renderer/model/phase_function.h"

namespace cloudsvc {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

// Fractional part of x / period in [0, 1), computed in double so that offsets of
// thousands of km (or decades of wind drift) keep sub-millimetre precision.
double wrap01(double x, double period) {
  double f = std::fmod(x / period, 1.0);
  return f < 0.0 ? f + 1.0 : f;
}

glm::vec4 wrapped_offset(const glm::dvec3& world_m, double period) {
  return {static_cast<float>(wrap01(world_m.x, period)), static_cast<float>(wrap01(world_m.y, period)),
          static_cast<float>(wrap01(world_m.z, period)), 0.0f};
}

}  // namespace

double horizon_reach_m(double R, double h, double H) {
  return std::sqrt(std::max(h, 0.0) * (2.0 * R + std::max(h, 0.0))) + std::sqrt(std::max(H, 0.0) * (2.0 * R + H));
}

NoiseQuantiles noise_quantiles(const weather::NoiseVolume& v) {
  std::array<std::size_t, 256> hist{};
  for (std::uint8_t x : v.data) ++hist[x];
  NoiseQuantiles q{};
  const double n = static_cast<double>(v.data.size());
  std::size_t acc = 0;
  int value = 0;
  for (int i = 0; i < 16; ++i) {
    const double target = n * i / 15.0;
    while (value < 255 && static_cast<double>(acc + hist[static_cast<size_t>(value)]) < target) acc += hist[static_cast<size_t>(value++)];
    q[static_cast<size_t>(i)] = static_cast<float>(value) / 255.0f;
  }
  q[0] = 0.0f;
  q[15] = 1.0f;
  return q;
}

FrameUniforms make_frame_uniforms(const ViewRequest& view, const weather::Weather& weather,
                                  const RenderQuality& quality, const ResourceFacts& resources,
                                  const WindAnchor* wind_anchor) {
  const NoiseQuantiles& base_quantiles = resources.base_quantiles;
  FrameUniforms u{};
  const geo::Geodetic& pos = view.position;
  const glm::dmat3 enu_to_ecef = geo::enu_to_ecef(pos.lat_deg, pos.lon_deg);
  u.enu_to_ecef = glm::mat4(glm::mat3(enu_to_ecef));

  const geo::BodyAxes axes = geo::body_axes_enu(view.attitude);
  u.camera_forward = glm::vec4(glm::vec3(axes.forward), 0.0f);
  u.camera_right = glm::vec4(glm::vec3(axes.right), 0.0f);
  u.camera_up = glm::vec4(glm::vec3(axes.up), 0.0f);
  const double tan_h = std::tan(0.5 * view.fov_deg * kDegToRad);
  const double tan_v = tan_h * static_cast<double>(view.height) / static_cast<double>(view.width);
  u.view = glm::vec4(static_cast<float>(tan_h), static_cast<float>(tan_v), static_cast<float>(view.width),
                     static_cast<float>(view.height));

  // Shell: osculating sphere at the camera. Ground at altitude 0, or just below a camera
  // that is below the ellipsoid (no terrain or geoid model yet).
  const double R = geo::gaussian_radius(pos.lat_deg);
  const double h = pos.alt_m;
  const double ground_alt = std::min(0.0, h - 1.0);
  double highest = 12000.0;
  for (const auto& l : weather.layers) highest = std::max(highest, l.top_m);
  const double reach = horizon_reach_m(R, h - ground_alt, highest);
  u.planet = glm::vec4(static_cast<float>(R), static_cast<float>(h), static_cast<float>(ground_alt),
                       static_cast<float>(reach));

  const geo::SolarPosition sp = geo::solar_position(view.unix_time_s, pos.lat_deg, pos.lon_deg);
  const double el = sp.elevation_deg * kDegToRad, az = sp.azimuth_deg * kDegToRad;
  u.sun_dir = glm::vec4(static_cast<float>(std::cos(el) * std::sin(az)), static_cast<float>(std::cos(el) * std::cos(az)),
                        static_cast<float>(std::sin(el)), static_cast<float>(std::cos(kSunAngularRadiusDeg * kDegToRad)));
  u.sun_irradiance = glm::vec4(kSolarIrradiance[0], kSolarIrradiance[1], kSolarIrradiance[2], 0.0f);
  u.ground_albedo = glm::vec4(kGroundAlbedo[0], kGroundAlbedo[1], kGroundAlbedo[2], kNightSkyRadiance);
  u.quality = glm::vec4(static_cast<float>(quality.primary_steps), static_cast<float>(quality.light_steps),
                        static_cast<float>(quality.ms_octaves), static_cast<float>(quality.ground_shadow_steps));
  u.ms_params = glm::vec4(static_cast<float>(quality.ms_a), static_cast<float>(quality.ms_b),
                          static_cast<float>(quality.ms_c), static_cast<float>(quality.step_growth_ref_m));
  // Aerial perspective reaches the farthest visible ground or cloud (hundreds of km).
  u.ap_params = glm::vec4(static_cast<float>(std::max(reach, 1000.0)), static_cast<float>(resources.weather_map_height),
                          resources.weather_blend, 0.0f);
  // Skips: long steps in empty air, and LOD against the angle one pixel subtends (rad).
  u.march = glm::vec4(static_cast<float>(std::max(1, quality.long_step_factor)), quality.level_of_detail ? 1.0f : 0.0f,
                      static_cast<float>(2.0 * tan_h / view.width * std::max(1, quality.cloud_resolution_divisor)),
                      resources.detail_mean);
  // Light marches stop once the sun's beam is spent: past the cut-off for the octave that
  // decays slowest (octave k decays as e^(-a^k tau), cloud_march.comp: the last for a < 1,
  // the first for a >= 1).
  const double slowest = std::pow(std::min(quality.ms_a, 1.0), std::max(0, quality.ms_octaves - 1));
  const double light_cut = quality.light_march_cutoff > 0.0 ? quality.light_march_cutoff / slowest : 1e30;
  u.skips = glm::vec4(quality.coverage_pyramid && resources.coverage_pyramid ? 1.0f : 0.0f,
                      static_cast<float>(std::min(light_cut, 1e30)), 0.0f, 0.0f);
  const auto& ps = resources.weather_pole_south;
  const auto& pn = resources.weather_pole_north;
  u.weather_pole_south = glm::vec4(ps[0], ps[1], ps[2], ps[3]);
  u.weather_pole_north = glm::vec4(pn[0], pn[1], pn[2], pn[3]);

  for (int i = 0; i < 4; ++i)
    u.noise_quantiles[i] = glm::vec4(base_quantiles[4 * i], base_quantiles[4 * i + 1], base_quantiles[4 * i + 2],
                                     base_quantiles[4 * i + 3]);

  const glm::dvec3 cam_ecef = geo::geodetic_to_ecef(pos);
  const int n_layers = std::min<int>(static_cast<int>(weather.layers.size()), kGpuMaxLayers);
  for (int i = 0; i < n_layers; ++i) {
    const weather::CloudLayer& l = weather.layers[static_cast<size_t>(i)];
    const weather::CloudTypeTraits& tr = weather::cloud_type_traits(l.type);
    const model::JdDParams ph = model::jdd_params(l.droplet_diameter_um);
    const double base_period = tr.noise_scale_m;
    const double detail_period = base_period / 8.0;
    // Wind: the field is sampled at rot * x (renderer/wind_drift.h); the camera's
    // rotated ECEF position is wrapped per period in double, the GPU adds rot * p.
    const WindAnchor& anchor = wind_anchor ? *wind_anchor : WindAnchor{pos, view.unix_time_s};
    const glm::dmat3 rot = wind_rotation(l.wind, anchor, view.unix_time_s);
    // Noise space: world positions with altitude scaled by k along the ellipsoid normal,
    // f(X) = X + (k - 1) a(X) n(X), a fixed map of the world (no camera dependence).
    const glm::dvec3 cam_normal = enu_to_ecef[2];
    const glm::dvec3 cam_field = rot * (cam_ecef + (tr.noise_vertical_scale - 1.0) * h * cam_normal);
    CloudLayerGpu& g = u.layers[i];
    g.altitude = glm::vec4(static_cast<float>(l.base_m), static_cast<float>(l.top_m), static_cast<float>(l.coverage),
                           static_cast<float>(l.density_scale));
    g.optics = glm::vec4(static_cast<float>(model::cloud_extinction_per_m(l.droplet_diameter_um)),
                         static_cast<float>(ph.g_hg), static_cast<float>(ph.g_d), static_cast<float>(ph.alpha));
    g.optics2 = glm::vec4(static_cast<float>(ph.w_d), static_cast<float>(1.0 / base_period),
                          static_cast<float>(1.0 / detail_period), tr.profile.base_erosion);
    g.profile = glm::vec4(tr.profile.bottom_ramp, tr.profile.top_ramp, tr.profile.top_weight,
                          static_cast<float>(tr.noise_vertical_scale));
    g.base_offset = wrapped_offset(cam_field, base_period);
    g.base_offset.w = tr.stratiform ? 1.0f : 0.0f;
    g.detail_offset = wrapped_offset(cam_field, detail_period);
    g.noise_rotation = glm::mat4(glm::mat3(rot * enu_to_ecef));
  }
  u.counts = glm::ivec4(n_layers, static_cast<int>(view.frame_index % 65536u),
                        quality.count_density_evaluations ? 1 : 0, quality.footprint_jitter ? 1 : 0);
  return u;
}

}  // namespace cloudsvc
