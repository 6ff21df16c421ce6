// ICAO Standard Atmosphere (standard_atmosphere.h).
#include "weather/standard_atmosphere.h"

#include <cmath>
#include <limits>

namespace cloudsvc::weather {

namespace {

// Base of each layer: geopotential altitude (m), temperature (K), pressure (Pa) and the
// temperature gradient above it (K per geopotential metre); ICAO Doc 7488/3, Table D.
struct AtmosphereLayer {
  double base_m, temperature_K, pressure_Pa, lapse_Kpm;
};
constexpr AtmosphereLayer kLayers[] = {
    {0.0, 288.15, 101325.0, -0.0065},
    {11000.0, 216.65, 22632.06, 0.0},
    {20000.0, 216.65, 5474.889, 0.001},
};

}  // namespace

double standard_geopotential_altitude_m(double pressure_Pa) {
  if (!(pressure_Pa > 0.0) || !std::isfinite(pressure_Pa)) return std::numeric_limits<double>::quiet_NaN();
  const AtmosphereLayer* layer = &kLayers[0];
  for (const AtmosphereLayer& l : kLayers)
    if (pressure_Pa <= l.pressure_Pa) layer = &l;
  const double g_over_r = kStandardGravity_mps2 / kAirGasConstant_JpkgK;
  if (layer->lapse_Kpm == 0.0)  // isothermal: p = pb exp(-g (H - Hb) / (R T))
    return layer->base_m + layer->temperature_K / g_over_r * std::log(layer->pressure_Pa / pressure_Pa);
  // T = Tb + L (H - Hb), p = pb (T / Tb)^(-g / (R L))  =>  H = Hb + Tb / L ((p / pb)^(-R L / g) - 1)
  const double ratio = std::pow(pressure_Pa / layer->pressure_Pa, -layer->lapse_Kpm / g_over_r);
  return layer->base_m + layer->temperature_K / layer->lapse_Kpm * (ratio - 1.0);
}

double geometric_from_geopotential_m(double geopotential_altitude_m) {
  const double h = geopotential_altitude_m;
  return kStandardEarthRadius_m * h / (kStandardEarthRadius_m - h);
}

double standard_pressure_altitude_m(double pressure_Pa) {
  return geometric_from_geopotential_m(standard_geopotential_altitude_m(pressure_Pa));
}

}  // namespace cloudsvc::weather
