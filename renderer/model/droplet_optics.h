// Cloud extinction from droplet microphysics (Bouthors et al. 2008 §3.1-3.2; docs/SOURCES.md):
//   sigma_t = N0 * Q_ext * pi * r^2,  r = d / 2
// with N0 the droplet number density (default 300 cm^-3 = 3e8 m^-3, Bouthors et al. 2008 §3.2) and
// Q_ext ~= 2 (large-particle limit of Mie extinction efficiency). Single-scattering
// albedo of cloud water in the visible is ~1.
#pragma once

#include "weather/cloud_water.h"

namespace cloudsvc::model {

constexpr double kDefaultDropletNumberDensity_m3 = weather::kDropletNumberDensity_m3;  // N0, m^-3 (300 cm^-3)
constexpr double kCloudQext = 2.0;                          // extinction efficiency

// Extinction coefficient (m^-1) of cloud with droplets of the given diameter (um).
double cloud_extinction_per_m(double diameter_um,
                              double number_density_m3 = kDefaultDropletNumberDensity_m3,
                              double q_ext = kCloudQext);

}  // namespace cloudsvc::model
