// Template implementation of atmo::integrate_inscatter (included by reference_atmosphere.h).
#pragma once

#include <algorithm>
#include <cmath>

namespace cloudsvc::reference::atmo {

namespace detail {

// Two-point Gauss-Legendre nodes on a step [t, t + dt]: midpoint -+ dt / (2 sqrt 3),
// weights dt / 2 each (exact for cubics).
constexpr double kGauss2Offset = 0.28867513459481288225;

}  // namespace detail

template <class Extinction>
glm::dvec3 integrate_optical_depth(double r, double mu, double length, double step_m, const Extinction& extinction) {
  glm::dvec3 tau(0.0);
  const auto radius_at = [&](double t) { return std::sqrt(std::max(r * r + t * t + 2.0 * r * mu * t, 0.0)); };
  double t = 0.0;
  while (t < length) {
    const double r_t = radius_at(t);
    const double dt = std::min(altitude_step(r_t, (r * mu + t) / r_t, step_m), length - t);
    const double tm = t + 0.5 * dt, h = detail::kGauss2Offset * dt;
    tau += 0.5 * dt * (extinction(radius_at(tm - h) - kBottomRadius) + extinction(radius_at(tm + h) - kBottomRadius));
    t += dt;
  }
  return tau;
}

template <class SunTransmittance, class MultipleScattering>
RayInscatter integrate_inscatter(double r0, const glm::dvec3& d, const glm::dvec3& sun, double t_end,
                                 bool skip_above_top, double step_m, double max_step_m,
                                 const SunTransmittance& sun_transmittance, const MultipleScattering& psi_ms,
                                 double aerosol_scale) {
  RayInscatter out;
  const glm::dvec3 start(0.0, 0.0, r0);
  const double nu = glm::dot(d, sun);
  const double phase_r = rayleigh_phase(nu), phase_m = mie_phase(nu);
  double t = 0.0;
  while (t < t_end) {
    const glm::dvec3 x0 = start + t * d;
    const double r_t = glm::length(x0);
    const double dt = std::min({altitude_step(r_t, glm::dot(x0, d) / r_t, step_m), max_step_m, t_end - t});
    const glm::dvec3 x = start + (t + 0.5 * dt) * d;  // midpoint
    t += dt;
    const double rx = glm::length(x);
    const double alt = rx - kBottomRadius;
    if (skip_above_top && alt >= kThickness) continue;
    const Medium m = medium_at(alt, aerosol_scale);
    const double mu_sun = glm::dot(x, sun) / rx;
    const glm::dvec3 t_sun = sun_transmittance(alt, mu_sun);
    const glm::dvec3 sigma_s = m.rayleigh_scattering + glm::dvec3(m.mie_scattering);
    const glm::dvec3 S = (m.rayleigh_scattering * phase_r + glm::dvec3(m.mie_scattering * phase_m)) * t_sun +
                         sigma_s * psi_ms(alt, mu_sun);
    for (int c = 0; c < 3; ++c) {  // (1 - e^{-sigma dt}) / sigma via expm1: no 0/0 as sigma -> 0
      const double em1 = std::expm1(-m.extinction[c] * dt);  // e^{-sigma dt} - 1
      const double weight = m.extinction[c] > 0.0 ? -em1 / m.extinction[c] : dt;
      out.radiance[c] += out.transmittance[c] * S[c] * weight;
      out.transmittance[c] *= 1.0 + em1;
    }
  }
  return out;
}

}  // namespace cloudsvc::reference::atmo
