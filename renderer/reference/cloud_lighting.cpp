// Converged cloud lighting pieces (see cloud_lighting.h).
#include "renderer/reference/cloud_lighting.h"

#include "renderer/model/ms_source_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/reference/shell_crossings.h"

namespace cloudsvc::reference {

namespace {
constexpr double kCumulusPeriod_m = 8000.0;
constexpr double kCumulusPeakSigma_per_m = 0.15;  // 0.1885 /m (d = 20 um) * 0.40 * 2

// The layer's full nominal optical depth: peak extinction times density scale times
// thickness (a homogeneous layer at full coverage) above the base raised by a textured base's
// mean lift (CloudField::nominal_base_m).
double nominal_optical_depth(const ReferenceLayer& L) {
  return L.sigma_max_per_m * L.density_scale * (L.top_m - CloudField::nominal_base_m(L));
}
}  // namespace

double layer_step_scale(const ReferenceLayer& layer) {
  const double peak_sigma = layer.sigma_max_per_m * layer.density_scale * 2.0;
  // k > 1 would make the features vertically smaller than the period says (none does yet).
  const double by_features = layer.base_period_m / kCumulusPeriod_m / std::max(layer.noise_vertical_scale, 1.0);
  const double by_optics = peak_sigma > 0.0 ? kCumulusPeakSigma_per_m / peak_sigma : 8.0;
  return std::clamp(std::min(by_features, by_optics), 1.0, 8.0);
}

double light_optical_depth(const CloudField& field, int li, const glm::dvec3& p, double alt, const glm::dvec3& sun,
                           double mu_s, double step_m, double tau_stop, std::uint64_t& evals, double* marched_m) {
  const ShellFrame& s = field.scene().shell;
  const ReferenceLayer& L = field.scene().layers[static_cast<std::size_t>(li)];
  double len = 0.0;
  if (const auto top = sphere_crossings(s.radius_m, alt, L.top_m, mu_s); top && top->t1 > 0.0) len = top->t1;
  if (const auto base = sphere_crossings(s.radius_m, alt, L.base_m, mu_s); base && base->t0 > 0.0)
    len = std::min(len, base->t0);
  len = std::min(len, kLightMarchCap_m);
  if (marched_m) *marched_m = 0.0;
  if (len <= 0.0) return 0.0;
  const int n = std::max(1, static_cast<int>(std::ceil(len / step_m)));
  const double dt = len / n;
  double tau = 0.0;
  int j = 0;
  for (; j < n && tau < tau_stop; ++j) {
    const glm::dvec3 x = p + sun * ((j + 0.5) * dt);
    tau += field.sample(li, x, s.altitude_of(x), false, evals).sigma_t * dt;
  }
  if (marched_m) *marched_m = j * dt;
  return tau;
}

SunSlab vertical_sun_slab(const ColumnDepths& column, const glm::dvec3& up, const glm::dvec3& sun, const glm::dvec3& w) {
  const double mu_s = glm::dot(up, sun), w_up = glm::dot(w, up);
  const glm::dvec3 sun_h = sun - mu_s * up, w_h = w - w_up * up;
  const double hh = glm::dot(sun_h, sun_h) * glm::dot(w_h, w_h);
  return {mu_s, column.above, column.below, w_up, hh > 1e-24 ? glm::dot(sun_h, w_h) / std::sqrt(hh) : 1.0};
}

double sun_window(double marched_m, double mu_s, double to_top_m) {
  if (!(to_top_m > 0.0)) return 1.0;
  return std::clamp(marched_m * std::max(mu_s, 0.0) / to_top_m, 0.0, 1.0);
}

SunSlab tilted_sun_slab(const ColumnDepths& column, double tau_sun, double window, const glm::dvec3& up,
                        const glm::dvec3& sun, const glm::dvec3& w) {
  const double mu_s = glm::dot(up, sun);
  const double s_h = std::sqrt(std::max(1.0 - mu_s * mu_s, 0.0));  // the sun's component across the vertical
  if (!(mu_s > 0.0) || s_h < 1e-9) return vertical_sun_slab(column, up, sun, w);  // no sun, or overhead
  const double f = std::clamp(window, 0.0, 1.0);
  const double mu = std::clamp(f * column.above / std::max(tau_sun, 1e-30), mu_s, 1.0);
  SunSlab slab;
  slab.mu = mu;
  slab.above = mu * tau_sun + (1.0 - f) * column.above;
  slab.below = column.below + std::max(column.above - slab.above, 0.0);
  // the normal: in the plane of up and sun, at cosine mu from the sun (mu = mu_s: up)
  const glm::dvec3 towards_up = (up - mu_s * sun) / s_h;
  const glm::dvec3 n = mu * sun + std::sqrt(std::max(1.0 - mu * mu, 0.0)) * towards_up;
  slab.w_n = glm::dot(w, n);
  const glm::dvec3 sun_t = sun - mu * n, w_t = w - slab.w_n * n;
  const double tt = glm::dot(sun_t, sun_t) * glm::dot(w_t, w_t);
  slab.cos_phi = tt > 1e-24 ? glm::dot(sun_t, w_t) / std::sqrt(tt) : 1.0;
  return slab;
}

ColumnDepths column_optical_depths(const CloudField& field, int li, const glm::dvec3& p, double alt, double step_m,
                                   std::uint64_t& evals) {
  const glm::dvec2 below_above = field.column_depths(
      li, p, alt, [step_m](double len) { return std::max(1, static_cast<int>(std::ceil(len / step_m))); }, evals);
  return {below_above.y, below_above.x};
}

ColumnDepths nominal_column_depths(const ReferenceLayer& L, double alt, double coverage) {
  const double sigma_nominal = L.sigma_max_per_m * L.density_scale * coverage;
  return {sigma_nominal * std::max(L.top_m - alt, 0.0), sigma_nominal * std::max(alt - CloudField::nominal_base_m(L), 0.0)};
}

double layer_sun_optical_depth(const CloudField& field, int li, const glm::dvec3& p, double alt, const glm::dvec3& sun,
                               double mu_s, double light_step_m, std::uint64_t& evals) {
  const ShellFrame& s = field.scene().shell;
  const ReferenceLayer& L = field.scene().layers[static_cast<std::size_t>(li)];
  const auto top = sphere_crossings(s.radius_m, alt, L.top_m, mu_s);
  if (!top || top->t1 <= 0.0) return 0.0;
  const auto base = sphere_crossings(s.radius_m, alt, L.base_m, mu_s);
  const double t_base = (base && base->t1 > 0.0) ? base->t1 : 0.0;
  const double t_top = top->t1;
  if (t_top <= t_base) return 0.0;
  const double step = light_step_m * layer_step_scale(L);
  const int n = std::max(1, static_cast<int>(std::ceil((t_top - t_base) / step)));
  const double dt = (t_top - t_base) / n;
  double tau = 0.0;
  for (int j = 0; j < n; ++j) {
    const glm::dvec3 x = p + sun * (t_base + (j + 0.5) * dt);
    tau += field.sample(li, x, s.altitude_of(x), false, evals).sigma_t * dt;
  }
  return tau;
}

double ground_shadow_optical_depth(const CloudField& field, const glm::dvec3& p, double ground_alt,
                                   const glm::dvec3& sun, double mu_s, double light_step_m, std::uint64_t& evals) {
  double tau = 0.0;
  for (std::size_t li = 0; li < field.scene().layers.size(); ++li)
    tau += layer_sun_optical_depth(field, static_cast<int>(li), p, ground_alt, sun, mu_s, light_step_m, evals);
  return tau;
}

double layers_above_optical_depth(const CloudField& field, int li, const glm::dvec3& p, double alt,
                                  const glm::dvec3& sun, double mu_s, double light_step_m, std::uint64_t& evals) {
  if (mu_s <= 0.0) return 0.0;
  const auto& layers = field.scene().layers;
  const double top = layers[static_cast<std::size_t>(li)].top_m;
  double tau = 0.0;
  for (std::size_t lj = 0; lj < layers.size(); ++lj)
    if (static_cast<int>(lj) != li && layers[lj].base_m >= top)
      tau += layer_sun_optical_depth(field, static_cast<int>(lj), p, alt, sun, mu_s, light_step_m, evals);
  return tau;
}

LightFromAbove layers_above_light(double tau, double mu_s, double r_low) {
  if (!(tau > 0.0)) return {};
  const double tau_v = tau * std::max(mu_s, 0.0);
  const double T_dif = slab_diffuse_transmittance(tau_v);
  const double gain = 1.0 / (1.0 - std::clamp(r_low, 0.0, 1.0) * (1.0 - T_dif));
  const double direct = std::exp(-tau);
  const double sun_diffuse =
      mu_s > 0.0 ? std::max(slab_beam_transmittance(tau_v, std::max(mu_s, 0.05)) * gain - direct, 0.0) : 0.0;
  return {direct, T_dif * gain, sun_diffuse};
}

double layer_diffuse_reflectance(const ReferenceLayer& L, double coverage) {
  const double tau_cloud = nominal_optical_depth(L);
  return std::clamp(coverage, 0.0, 1.0) * (1.0 - slab_diffuse_transmittance(tau_cloud));
}

glm::dvec3 sun_phase(const model::JdDParams& phase, const model::PhaseTable* mie, double cos_view_sun, double tau) {
  glm::dvec3 p(model::peak_beam_phase(cos_view_sun, tau, phase));
  if (mie) p += (mie->at_cos(cos_view_sun) - glm::dvec3(model::jdd_phase(cos_view_sun, phase))) * std::exp(-tau);
  return p;
}

glm::dvec3 ground_cloud_gain(const glm::dvec3& albedo, double tau) {
  return 1.0 / (1.0 - albedo * (1.0 - slab_diffuse_transmittance(tau)));
}

glm::dvec3 diffuse_inscatter(const ReferenceLayer& L, const ColumnDepths& column, const SunSlab& sun_slab, double mu_s,
                             double coverage, const glm::dvec3& e_sun, const glm::dvec3& t_atm,
                             const glm::dvec3& e_sky_here, const glm::dvec3& t_atm_ground,
                             const glm::dvec3& e_sky_ground, const glm::dvec3& ground_albedo, double w_up,
                             const LightFromAbove& above) {
  const double sim = model::ms_similarity_scale(L.phase);
  const double tau_above = column.above, tau_below = column.below;
  const double mu_pos = std::max(mu_s, 0.0);
  glm::dvec3 J_sun(0.0);
  if (mu_pos > 0.0) {
    const double phi_deg = std::acos(std::clamp(sun_slab.cos_phi, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    J_sun = e_sun * t_atm *
            (above.direct * sun_slab.mu *
             model::ms_source_table().lookup(sim * sun_slab.above, sim * sun_slab.below, sun_slab.mu, sun_slab.w_n, phi_deg));
  }
  // diffuse light onto the layer's top: the sky's, and the sun's the layers above scatter
  const glm::dvec3 E_sky = e_sun * (e_sky_here * above.sky + t_atm * (mu_pos * above.sun_diffuse));
  const double mu0 = std::max(mu_pos, 0.05);
  // The ground under the layer: a fraction 1 - c in the clear, c under cloud of the layer's
  // full optical depth (independent columns), with the round trips to the cloud's base.
  const double c = std::clamp(coverage, 0.0, 1.0);
  const double tau_cloud = nominal_optical_depth(L);
  const double T_sun_ground = 1.0 - c + c * (mu_pos > 0.0 ? slab_beam_transmittance(tau_cloud, mu0) : 0.0);
  const double T_sky_ground = 1.0 - c + c * slab_diffuse_transmittance(tau_cloud);
  const glm::dvec3 E_up = ground_albedo * ground_cloud_gain(ground_albedo * c, tau_cloud) * e_sun *
                          (t_atm_ground * mu_pos * (above.direct * T_sun_ground + above.sun_diffuse * T_sky_ground) +
                           e_sky_ground * (above.sky * T_sky_ground));
  // the sky's light enters through the layer's top, the ground's through its base: the
  // Monte Carlo source of diffuse incident light, the base's turned upside down
  const model::MsSourceTable& iso = model::ms_diffuse_incidence_table();
  const glm::dvec3 J = E_sky * iso.lookup(sim * tau_above, sim * tau_below, 1.0, w_up, 0.0) +
                       E_up * iso.lookup(sim * tau_below, sim * tau_above, 1.0, -w_up, 0.0);
  return J_sun + J;
}

}  // namespace cloudsvc::reference
