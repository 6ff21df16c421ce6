// Psi_ms and E_sky tables of the converged model (see atmosphere_tables.h).
#include "renderer/reference/atmosphere_tables.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <tuple>

#include "common/parallel_for.h"
#include "renderer/reference/quadrature.h"
#include "renderer/reference/reference_atmosphere.h"

namespace cloudsvc::reference {

namespace {

constexpr double kPi = std::numbers::pi;

// Table altitudes (m): dense where clouds, the ground and most cameras are. Psi_ms is
// needed along sky rays up to the top of the atmosphere; E_sky only at cloud samples and
// the ground (weather::validate keeps layers below 20 km).
std::vector<double> psi_altitudes() {
  return {0.0,     250.0,   500.0,   750.0,   1000.0,  1500.0,  2000.0,  2500.0,  3000.0,
          4000.0,  5000.0,  6000.0,  7000.0,  8000.0,  10000.0, 12000.0, 14000.0, 16000.0,
          18000.0, 20000.0, 25000.0, 30000.0, 40000.0, 50000.0, 60000.0, 80000.0, 100000.0};
}
std::vector<double> sky_irradiance_altitudes() {
  return {0.0,    250.0,  500.0,  750.0,   1000.0,  1500.0,  2000.0,  2500.0,  3000.0,  4000.0,
          5000.0, 6000.0, 7000.0, 8000.0, 10000.0, 12000.0, 14000.0, 16000.0, 18000.0, 20000.0};
}

glm::dvec3 sun_in_x_z_plane(double mu_sun) {
  return {std::sqrt(std::max(0.0, 1.0 - mu_sun * mu_sun)), 0.0, mu_sun};
}

glm::dvec3 direction(double mu, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return {s * std::cos(phi), s * std::sin(phi), mu};
}

}  // namespace

bool AtmosphereTableSettings::operator<(const AtmosphereTableSettings& o) const {
  return std::tie(step_m, max_step_m, mu_sun_nodes, ms_zenith_nodes, ms_azimuth_nodes, sky_zenith_nodes,
                  sky_azimuth_nodes, aerosol_scale) < std::tie(o.step_m, o.max_step_m, o.mu_sun_nodes, o.ms_zenith_nodes,
                                                               o.ms_azimuth_nodes, o.sky_zenith_nodes,
                                                               o.sky_azimuth_nodes, o.aerosol_scale);
}

MuAltitudeTable::MuAltitudeTable(int mu_nodes, std::vector<double> altitudes_m) : altitudes_(std::move(altitudes_m)) {
  const int n = std::max(mu_nodes, 2);
  for (int i = 0; i < n; ++i) {
    const double x = -1.0 + 2.0 * i / (n - 1);
    mus_.push_back(0.25 * x + 0.75 * x * x * x);
  }
  log_values_.assign(mus_.size() * altitudes_.size(), glm::dvec3(std::log(1e-300)));
}

void MuAltitudeTable::set(std::size_t i_mu, std::size_t i_alt, const glm::dvec3& value) {
  log_values_[i_alt * mus_.size() + i_mu] = glm::log(glm::max(value, glm::dvec3(1e-300)));
}

namespace {
// Index i of the cell [nodes[i], nodes[i + 1]] holding x (clamped) and the weight of i + 1.
std::pair<std::size_t, double> locate(const std::vector<double>& nodes, double x) {
  x = std::clamp(x, nodes.front(), nodes.back());
  const auto it = std::upper_bound(nodes.begin(), nodes.end(), x);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - nodes.begin() - 1, 0)),
                                               nodes.size() - 2);
  return {i, (x - nodes[i]) / (nodes[i + 1] - nodes[i])};
}
}  // namespace

glm::dvec3 MuAltitudeTable::lookup(double altitude_m, double mu_sun) const {
  const auto [i, a] = locate(mus_, mu_sun);
  const auto [j, b] = locate(altitudes_, altitude_m);
  const std::size_t n = mus_.size();
  // Bilinear in the logarithm: both quantities fall roughly exponentially with altitude
  // and towards the night side, where linear interpolation would overshoot.
  const auto v = [&](std::size_t ii, std::size_t jj) { return log_values_[jj * n + ii]; };
  return glm::exp(glm::mix(glm::mix(v(i, j), v(i + 1, j), a), glm::mix(v(i, j + 1), v(i + 1, j + 1), a), b));
}

// ---- fine transmittance table (Bruneton 2017 parameterisation, nodes at the corners)

void AtmosphereTables::build_fine_transmittance() {
  fine_.optical_depth.assign(static_cast<std::size_t>(fine_.n_mu) * fine_.n_r, glm::dvec3(0.0));
  const double H = std::sqrt(atmo::kTopRadius * atmo::kTopRadius - atmo::kBottomRadius * atmo::kBottomRadius);
  parallel_for(fine_.n_r, settings_.threads, [&](int j) {
    const double rho = H * j / (fine_.n_r - 1);
    const double r = std::sqrt(rho * rho + atmo::kBottomRadius * atmo::kBottomRadius);
    const double d_min = atmo::kTopRadius - r, d_max = rho + H;
    for (int i = 0; i < fine_.n_mu; ++i) {
      const double d = d_min + (d_max - d_min) * i / (fine_.n_mu - 1);
      const double mu = d <= 0.0 ? 1.0 : std::clamp((H * H - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0);
      fine_.optical_depth[static_cast<std::size_t>(j) * fine_.n_mu + i] = atmo::optical_depth(r, mu, d, settings_.step_m, settings_.aerosol_scale);
    }
  });
}

glm::dvec3 AtmosphereTables::tabulated_transmittance(double altitude_m, double mu) const {
  const double r = atmo::radius_for_altitude(altitude_m);
  if (atmo::ray_hits_ground(r, mu)) return glm::dvec3(0.0);
  const double H = std::sqrt(atmo::kTopRadius * atmo::kTopRadius - atmo::kBottomRadius * atmo::kBottomRadius);
  const double rho = std::sqrt(std::max(r * r - atmo::kBottomRadius * atmo::kBottomRadius, 0.0));
  const double d = atmo::distance_to_top(r, mu);
  const double d_min = atmo::kTopRadius - r, d_max = rho + H;
  const double x_mu = std::clamp((d - d_min) / (d_max - d_min), 0.0, 1.0) * (fine_.n_mu - 1);
  const double x_r = std::clamp(rho / H, 0.0, 1.0) * (fine_.n_r - 1);
  const int i0 = std::min(static_cast<int>(x_mu), fine_.n_mu - 2), j0 = std::min(static_cast<int>(x_r), fine_.n_r - 2);
  const double a = x_mu - i0, b = x_r - j0;
  const auto v = [&](int i, int j) { return fine_.optical_depth[static_cast<std::size_t>(j) * fine_.n_mu + i]; };
  const glm::dvec3 tau = glm::mix(glm::mix(v(i0, j0), v(i0 + 1, j0), a), glm::mix(v(i0, j0 + 1), v(i0 + 1, j0 + 1), a), b);
  return glm::exp(-tau);
}

// ---- Psi_ms: Hillaire 2020 eqs. 5-10 (isotropic phase for the sun scattering, ground bounce)

glm::dvec3 AtmosphereTables::multiple_scattering_at(double altitude_m, double mu_sun, int zenith_nodes,
                                                    int azimuth_nodes, double step_m) const {
  const double step = step_m > 0.0 ? step_m : settings_.step_m;
  const double max_step = settings_.max_step_m * step / settings_.step_m;
  const int n_mu = zenith_nodes > 0 ? zenith_nodes : settings_.ms_zenith_nodes;
  const int n_phi = azimuth_nodes > 0 ? azimuth_nodes : settings_.ms_azimuth_nodes;
  const double r = atmo::radius_for_altitude(altitude_m);
  const glm::dvec3 sun = sun_in_x_z_plane(mu_sun);
  const glm::dvec3 start(0.0, 0.0, r);
  // Zenith cosines split at the horizon mu_h (the integrand jumps there: ground vs. limb)
  // and clustered towards it on both sides (grazing rays vary fastest).
  const double mu_h = -std::sqrt(std::max(0.0, 1.0 - (atmo::kBottomRadius / r) * (atmo::kBottomRadius / r)));
  QuadratureRule zenith = gauss_legendre_clustered(n_mu, mu_h, 1.0);
  const QuadratureRule below = gauss_legendre_clustered(n_mu, mu_h, -1.0);
  zenith.nodes.insert(zenith.nodes.end(), below.nodes.begin(), below.nodes.end());
  zenith.weights.insert(zenith.weights.end(), below.weights.begin(), below.weights.end());
  const double inv_4pi = 1.0 / (4.0 * kPi);
  glm::dvec3 L2(0.0), f_ms(0.0);
  for (std::size_t iz = 0; iz < zenith.nodes.size(); ++iz) {
    const double mu = zenith.nodes[iz];
    const bool ground = atmo::ray_hits_ground(r, mu);
    const double len = atmo::path_length(r, mu);
    for (int k = 0; k < n_phi; ++k) {
      const double phi = (k + 0.5) * kPi / n_phi;
      const double solid_angle = zenith.weights[iz] * (kPi / n_phi) * 2.0;  // x2: mirror image -phi
      const glm::dvec3 d = direction(mu, phi);
      glm::dvec3 T(1.0), L(0.0), F(0.0);
      double t = 0.0;
      while (t < len) {
        const glm::dvec3 x0 = start + t * d;
        const double r_t = glm::length(x0);
        const double dt = std::min({atmo::altitude_step(r_t, glm::dot(x0, d) / r_t, step), max_step, len - t});
        const glm::dvec3 x = start + (t + 0.5 * dt) * d;
        t += dt;
        const double rx = glm::length(x);
        const double alt = rx - atmo::kBottomRadius;
        const atmo::Medium m = atmo::medium_at(alt, settings_.aerosol_scale);
        const glm::dvec3 sigma_s = m.rayleigh_scattering + glm::dvec3(m.mie_scattering);
        const glm::dvec3 t_sun = tabulated_transmittance(alt, glm::dot(x, sun) / rx);
        for (int c = 0; c < 3; ++c) {
          const double em1 = std::expm1(-m.extinction[c] * dt);  // e^{-sigma dt} - 1
          const double w = m.extinction[c] > 0.0 ? -em1 / m.extinction[c] : dt;
          L[c] += T[c] * w * sigma_s[c] * t_sun[c] * inv_4pi;
          F[c] += T[c] * w * sigma_s[c];
          T[c] *= 1.0 + em1;
        }
      }
      if (ground) {
        const glm::dvec3 x = start + len * d;
        const double mu_g = glm::dot(glm::normalize(x), sun);
        L += T * tabulated_transmittance(0.0, mu_g) * std::max(mu_g, 0.0) * atmo::kGroundAlbedo / kPi;
      }
      L2 += L * solid_angle;
      f_ms += F * solid_angle;
    }
  }
  L2 *= inv_4pi;
  f_ms *= inv_4pi;
  return L2 / (glm::dvec3(1.0) - f_ms);
}

// ---- E_sky: irradiance on a horizontal surface from the sky dome (no direct sun)

glm::dvec3 AtmosphereTables::sky_irradiance_at(double altitude_m, double mu_sun, int zenith_nodes,
                                               int azimuth_nodes, double step_m) const {
  const double step = step_m > 0.0 ? step_m : settings_.step_m;
  const double max_step = settings_.max_step_m * step / settings_.step_m;
  const int n_mu = zenith_nodes > 0 ? zenith_nodes : settings_.sky_zenith_nodes;
  const int n_phi = azimuth_nodes > 0 ? azimuth_nodes : settings_.sky_azimuth_nodes;
  const double r = atmo::radius_for_altitude(altitude_m);
  const glm::dvec3 sun = sun_in_x_z_plane(mu_sun);
  // Zenith cosines clustered towards the horizontal (long, bright grazing paths).
  const QuadratureRule zenith = gauss_legendre_clustered(n_mu, 0.0, 1.0);
  const auto sun_t = [this](double alt, double mu) { return tabulated_transmittance(alt, mu); };
  const auto psi = [this](double alt, double mu) { return psi_ms_.lookup(alt, mu); };
  glm::dvec3 E(0.0);
  for (std::size_t iz = 0; iz < zenith.nodes.size(); ++iz) {
    const double mu = zenith.nodes[iz];
    for (int k = 0; k < n_phi; ++k) {
      const double phi = (k + 0.5) * kPi / n_phi;
      const double weight = zenith.weights[iz] * (kPi / n_phi) * 2.0 * mu;  // cos(theta) dw, mirror x2
      const atmo::RayInscatter s = atmo::integrate_inscatter(r, direction(mu, phi), sun, atmo::path_length(r, mu),
                                                             false, step, max_step, sun_t, psi, settings_.aerosol_scale);
      E += s.radiance * weight;
    }
  }
  return E;
}

AtmosphereTables::AtmosphereTables(const AtmosphereTableSettings& settings)
    : settings_(settings),
      psi_ms_(settings.mu_sun_nodes, psi_altitudes()),
      e_sky_(settings.mu_sun_nodes, sky_irradiance_altitudes()) {
  build_fine_transmittance();
  parallel_for(static_cast<int>(psi_ms_.altitudes().size()), settings_.threads, [&](int j) {
    const auto jj = static_cast<std::size_t>(j);
    for (std::size_t i = 0; i < psi_ms_.mus().size(); ++i)
      psi_ms_.set(i, jj, multiple_scattering_at(psi_ms_.altitudes()[jj], psi_ms_.mus()[i]));
  });
  parallel_for(static_cast<int>(e_sky_.altitudes().size()), settings_.threads, [&](int j) {
    const auto jj = static_cast<std::size_t>(j);
    for (std::size_t i = 0; i < e_sky_.mus().size(); ++i)
      e_sky_.set(i, jj, sky_irradiance_at(e_sky_.altitudes()[jj], e_sky_.mus()[i]));
  });
}

std::shared_ptr<const AtmosphereTables> atmosphere_tables(const AtmosphereTableSettings& settings) {
  static std::mutex mutex;
  static std::map<AtmosphereTableSettings, std::shared_ptr<const AtmosphereTables>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[settings];
  if (!slot) slot = std::make_shared<const AtmosphereTables>(settings);
  return slot;
}

}  // namespace cloudsvc::reference
