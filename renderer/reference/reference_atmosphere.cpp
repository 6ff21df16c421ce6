// Clear-sky atmosphere by direct integration (see reference_atmosphere.h).
#include "renderer/reference/reference_atmosphere.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cloudsvc::reference::atmo {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kOzonePeak_m = 25.0e3, kOzoneHalfWidth_m = 15.0e3;  // tent 10-25-40 km
double ozone_tent(double a) { return std::max(0.0, 1.0 - std::abs(a - kOzonePeak_m) / kOzoneHalfWidth_m); }
}  // namespace

Medium medium_at(double altitude_m, double aerosol_scale) {
  const double a = std::max(altitude_m, 0.0);
  const double rayleigh_density = std::exp(-a / kRayleighScaleHeight);
  const double mie_density = aerosol_scale * std::exp(-a / kMieScaleHeight);
  const double ozone_density = ozone_tent(a);
  Medium m;
  m.rayleigh_scattering = kRayleighScattering * rayleigh_density;
  m.mie_scattering = kMieScattering * mie_density;
  m.extinction = m.rayleigh_scattering + glm::dvec3(kMieExtinction * mie_density) + kOzoneAbsorption * ozone_density;
  return m;
}

glm::dvec3 max_extinction(double a0, double a1, double aerosol_scale) {
  const double lo = std::max(a0, 0.0), hi = std::max(a1, lo);
  const Medium m = medium_at(lo, aerosol_scale);  // the exponentials decrease with altitude
  return m.extinction + kOzoneAbsorption * (ozone_tent(std::clamp(kOzonePeak_m, lo, hi)) - ozone_tent(lo));
}

double rayleigh_phase(double nu) { return 3.0 / (16.0 * kPi) * (1.0 + nu * nu); }

// Cornette & Shanks 1992: p = 3/(8 pi) (1 - g^2)/(2 + g^2) (1 + nu^2) / (1 + g^2 - 2 g nu)^{3/2}.
double mie_phase(double nu) {
  const double g = kMieG, g2 = g * g;
  const double k = 3.0 / (8.0 * kPi) * (1.0 - g2) / (2.0 + g2);
  const double denom = 1.0 + g2 - 2.0 * g * nu;
  return k * (1.0 + nu * nu) / (denom * std::sqrt(denom));
}

double radius_for_altitude(double altitude_m) {
  return std::clamp(kBottomRadius + altitude_m, kBottomRadius + 1.0, kTopRadius - 1.0);
}

bool ray_hits_ground(double r, double mu) {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + kBottomRadius * kBottomRadius >= 0.0;
}

double distance_to_top(double r, double mu) {
  const double disc = r * r * (mu * mu - 1.0) + kTopRadius * kTopRadius;
  return std::max(0.0, -r * mu + std::sqrt(std::max(disc, 0.0)));
}

double distance_to_bottom(double r, double mu) {
  const double disc = r * r * (mu * mu - 1.0) + kBottomRadius * kBottomRadius;
  return std::max(0.0, -r * mu - std::sqrt(std::max(disc, 0.0)));
}

double path_length(double r, double mu) {
  return ray_hits_ground(r, mu) ? distance_to_bottom(r, mu) : distance_to_top(r, mu);
}

double altitude_step(double r, double mu, double step_m) {
  const double alt = std::max(r - kBottomRadius, 0.0);
  const double s = step_m * (1.0 + alt / 8000.0);
  return 2.0 * s / (std::abs(mu) + std::sqrt(mu * mu + 2.0 * s / r));
}

glm::dvec3 optical_depth(double r, double mu, double length, double step_m, double aerosol_scale) {
  return integrate_optical_depth(r, mu, length, step_m,
                                 [aerosol_scale](double alt) { return medium_at(alt, aerosol_scale).extinction; });
}

glm::dvec3 transmittance_to_space(double altitude_m, double mu, double step_m, double aerosol_scale) {
  const double r = radius_for_altitude(altitude_m);
  if (ray_hits_ground(r, mu)) return glm::dvec3(0.0);
  const glm::dvec3 tau = optical_depth(r, mu, distance_to_top(r, mu), step_m, aerosol_scale);
  return glm::exp(-tau);
}

}  // namespace cloudsvc::reference::atmo
