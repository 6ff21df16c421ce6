// Per-pixel radiance of the reference (see pixel_integrator.h).
#include "renderer/reference/pixel_integrator.h"

#include "renderer/model/ms_source_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "renderer/reference/cloud_lighting.h"
#include "renderer/reference/shell_crossings.h"

namespace cloudsvc::reference {

namespace {

constexpr double kPi = std::numbers::pi;

struct Interval {
  double t0 = 0.0, t1 = 0.0;
  int layer = 0;
};

// The parts of the ray (from the camera, altitude h, zenith cosine mu) inside layer L,
// clipped to [t_start, t_limit]: inside the top sphere and outside the base sphere. The
// distance to a sphere is convex along a line, so each sphere's inside is one interval.
void layer_intervals(const ShellFrame& s, const ReferenceLayer& L, int li, double mu, double t_start, double t_limit,
                     std::vector<Interval>& out) {
  const auto top = sphere_crossings(s.radius_m, s.camera_alt_m, L.top_m, mu);
  if (!top) return;
  const double a0 = std::max(top->t0, t_start), a1 = std::min(top->t1, t_limit);
  if (a0 >= a1) return;
  const auto base = sphere_crossings(s.radius_m, s.camera_alt_m, L.base_m, mu);
  if (!base || base->t1 <= a0 || base->t0 >= a1) {
    out.push_back({a0, a1, li});
    return;
  }
  if (base->t0 > a0) out.push_back({a0, base->t0, li});
  if (base->t1 < a1) out.push_back({base->t1, a1, li});
}

}  // namespace

PixelIntegrator::PixelIntegrator(const CloudField& field, const AtmosphereTables& tables,
                                 const ReferenceSettings& settings)
    : field_(field), scene_(field.scene()), tables_(tables), settings_(settings),
      e_sun_(kSolarIrradiance[0], kSolarIrradiance[1], kSolarIrradiance[2]),
      ground_albedo_(field.scene().ground_albedo),
      camera_atmo_radius_(atmo::radius_for_altitude(field.scene().shell.camera_alt_m)) {
  // The peak beam decays as e^{-w_D tau}, slowest for the smallest w_D; < cutoff beyond this.
  tau_stop_ = std::log(1.0 / settings.light_cutoff) / model::peak_beam_slowest_decay();
}

glm::dvec3 PixelIntegrator::sun_transmittance(double alt, double mu) const {
  return atmo::transmittance_to_space(alt, mu, settings_.atmosphere_step_m, scene_.aerosol_scale);
}

atmo::RayInscatter PixelIntegrator::air_along_ray(const glm::dvec3& dir, double t_end, bool skip_above_top) const {
  const auto sun_t = [this](double alt, double mu) { return sun_transmittance(alt, mu); };
  const auto psi = [this](double alt, double mu) { return tables_.multiple_scattering(alt, mu); };
  return atmo::integrate_inscatter(camera_atmo_radius_, dir, scene_.sun_local, t_end, skip_above_top,
                                   settings_.atmosphere_step_m,
                                   settings_.atmosphere_max_step_factor * settings_.atmosphere_step_m, sun_t, psi,
                                   scene_.aerosol_scale);
}

glm::dvec3 PixelIntegrator::cloud_inscatter(int li, const glm::dvec3& p, double alt, double coverage,
                                            const glm::dvec3& dir, std::uint64_t& evals) const {
  const double cos_view_sun = glm::dot(dir, scene_.sun_local);
  const ShellFrame& s = scene_.shell;
  const ReferenceLayer& L = scene_.layers[static_cast<std::size_t>(li)];
  const glm::dvec3& sun = scene_.sun_local;
  const double mu_s = glm::dot(s.up_at(p), sun);
  const glm::dvec3 t_atm = sun_transmittance(alt, mu_s);
  // what the layers above let through (layers_above_light)
  const LightFromAbove above =
      layers_above_light(layers_above_optical_depth(field_, li, p, alt, sun, mu_s, settings_.light_step_m, evals), mu_s,
                         layer_diffuse_reflectance(L, coverage));
  glm::dvec3 sun_light(0.0);
  const double step = settings_.light_step_m * layer_step_scale(L);
  double tau_sun = 0.0, marched_m = 0.0;
  if (std::max({t_atm.r, t_atm.g, t_atm.b}) > 0.0) {
    tau_sun = light_optical_depth(field_, li, p, alt, sun, mu_s, step, tau_stop_, evals, &marched_m);
    sun_light = e_sun_ * t_atm * (above.direct * sun_phase(L.phase, L.mie_phase.get(), cos_view_sun, tau_sun));
  }
  const double ground_alt = s.ground_alt_m;
  // the scattered light travels along -dir
  const glm::dvec3 up = s.up_at(p);
  const ColumnDepths column = settings_.column_depths
                                  ? column_optical_depths(field_, li, p, alt, step * settings_.column_step_factor, evals)
                                  : nominal_column_depths(L, alt, coverage);
  // the sun's slab: tilted towards the sun (needs the point's own column), or the column's
  // horizontal one (t_atm = 0 leaves the sun's source 0 whatever its slab)
  const SunSlab sun_slab = settings_.sun_slab_tilt && settings_.column_depths
                               ? tilted_sun_slab(column, tau_sun, sun_window(marched_m, mu_s, L.top_m - alt), up, sun, -dir)
                               : vertical_sun_slab(column, up, sun, -dir);
  const glm::dvec3 diffuse =
      diffuse_inscatter(L, column, sun_slab, mu_s, coverage, e_sun_, t_atm, tables_.sky_irradiance(alt, mu_s),
                        sun_transmittance(ground_alt, mu_s), tables_.sky_irradiance(ground_alt, mu_s), ground_albedo_,
                        -glm::dot(dir, up), above);
  return sun_light + diffuse;
}

PixelIntegrator::CloudMarch PixelIntegrator::march_clouds(const glm::dvec3& dir, double t_limit,
                                                          std::uint64_t& evals) const {
  CloudMarch m;
  std::vector<Interval> intervals;
  const ReferenceCamera& cam = scene_.camera;
  const CloudClip clip = cloud_clip(cam.near_m, cam.far_m, glm::dot(dir, cam.forward));
  for (std::size_t li = 0; li < scene_.layers.size(); ++li)
    layer_intervals(scene_.shell, scene_.layers[li], static_cast<int>(li), dir.z, clip.t0,
                    std::min(t_limit, clip.t1), intervals);
  std::sort(intervals.begin(), intervals.end(), [](const Interval& a, const Interval& b) { return a.t0 < b.t0; });
  for (const Interval& iv : intervals) {
    if (m.transmittance <= settings_.min_transmittance) break;
    const double step = settings_.cloud_step_m * layer_step_scale(scene_.layers[static_cast<std::size_t>(iv.layer)]);
    const double len = iv.t1 - iv.t0;
    const long long n = std::max(1LL, static_cast<long long>(std::ceil(len / step)));
    const double dt = len / static_cast<double>(n);
    for (long long k = 0; k < n && m.transmittance > settings_.min_transmittance; ++k) {
      const double t = iv.t0 + (static_cast<double>(k) + 0.5) * dt;
      const glm::dvec3 p = t * dir;
      const double alt = scene_.shell.altitude_of(p);
      const CloudSample c = field_.sample(iv.layer, p, alt, true, evals);
      if (c.sigma_t <= 0.0) continue;
      const glm::dvec3 S = cloud_inscatter(iv.layer, p, alt, c.coverage, dir, evals);
      const double scattered = -std::expm1(-c.sigma_t * dt);  // albedo 1: 1 - e^{-sigma dt}
      m.radiance += m.transmittance * scattered * S;
      m.weighted_depth += t * m.transmittance * scattered;
      m.transmittance *= std::exp(-c.sigma_t * dt);
    }
  }
  return m;
}

glm::dvec3 PixelIntegrator::ground_radiance(const glm::dvec3& dir, double t_ground, std::uint64_t& evals) const {
  const ShellFrame& s = scene_.shell;
  const glm::dvec3& sun = scene_.sun_local;
  const glm::dvec3 p = t_ground * dir;
  const double mu_s = glm::dot(s.up_at(p), sun);
  const double mu_pos = std::max(mu_s, 0.0);
  const glm::dvec3 t_atm = sun_transmittance(s.ground_alt_m, mu_s);
  double tau = 0.0;
  if (mu_s > 0.0 && !scene_.layers.empty())
    tau = ground_shadow_optical_depth(field_, p, s.ground_alt_m, sun, mu_s, settings_.light_step_m, evals);
  // sun: delta-Eddington beam transmittance of the clouds' vertical optical depth; sky: diffuse
  const double tau_v = tau * mu_pos;
  const double sun_through = mu_s > 0.0 ? slab_beam_transmittance(tau_v, std::max(mu_pos, 0.05)) : 0.0;
  const glm::dvec3 E = e_sun_ *
                       (t_atm * mu_pos * sun_through + tables_.sky_irradiance(s.ground_alt_m, mu_s) * slab_diffuse_transmittance(tau_v)) *
                       ground_cloud_gain(ground_albedo_, tau_v);
  const glm::dvec3 L_ground = ground_albedo_ / kPi * E;
  const atmo::RayInscatter air = air_along_ray(dir, t_ground, true);
  return L_ground * air.transmittance + e_sun_ * air.radiance;
}

glm::dvec3 PixelIntegrator::sky_radiance(const glm::dvec3& dir) const {
  const double r = camera_atmo_radius_;
  const atmo::RayInscatter air = air_along_ray(dir, atmo::path_length(r, dir.z), false);
  glm::dvec3 L = e_sun_ * air.radiance;
  const double cos_radius = std::cos(kSunAngularRadiusDeg * kPi / 180.0);
  if (glm::dot(dir, scene_.sun_local) > cos_radius) {
    const double solid_angle = 2.0 * kPi * (1.0 - cos_radius);
    L += e_sun_ / solid_angle * sun_transmittance(scene_.shell.camera_alt_m, dir.z);
  }
  return L + glm::dvec3(kNightSkyRadiance);
}

PixelRadiance PixelIntegrator::shade(const glm::dvec3& dir, std::uint64_t& evals) const {
  const ShellFrame& s = scene_.shell;
  const auto ground = sphere_crossings(s.radius_m, s.camera_alt_m, s.ground_alt_m, dir.z);
  const bool hits_ground = ground && ground->t0 >= 0.0;
  const double t_ground = hits_ground ? ground->t0 : std::numeric_limits<double>::infinity();

  const CloudMarch clouds = march_clouds(dir, t_ground, evals);
  // Behind a cloud whose transmittance fell below min_transmittance the background
  // contributes less than that fraction of its radiance: not evaluated (it would cost a
  // ground-shadow march or a sky integration per pixel for nothing).
  glm::dvec3 background(0.0);
  if (clouds.transmittance > settings_.min_transmittance)
    background = hits_ground ? ground_radiance(dir, t_ground, evals) : sky_radiance(dir);

  glm::dvec3 C = clouds.radiance;
  const double opacity = 1.0 - clouds.transmittance;
  if (opacity > 0.0) {
    const atmo::RayInscatter air = air_along_ray(dir, clouds.weighted_depth / opacity, true);
    C = C * air.transmittance + opacity * e_sun_ * air.radiance;
  }
  PixelRadiance out;
  out.radiance = C + clouds.transmittance * background;
  out.opacity = opacity;
  return out;
}

}  // namespace cloudsvc::reference
