// Cloud extinction from droplet microphysics (see droplet_optics.h).
#include "renderer/model/droplet_optics.h"

#include <numbers>

namespace cloudsvc::model {

// sigma_t [m^-1] = N0 [m^-3] * Q_ext * pi * r^2 [m^2], r = d / 2, d in micrometres.
double cloud_extinction_per_m(double diameter_um, double number_density_m3, double q_ext) {
  const double r_m = 0.5 * diameter_um * 1.0e-6;
  return number_density_m3 * q_ext * std::numbers::pi * r_m * r_m;
}

}  // namespace cloudsvc::model
