// The ICAO Standard Atmosphere (ICAO Doc 7488/3, 1993; identical to the ISO 2533:1975
// standard atmosphere below 32 km): the altitude at which it has a given pressure, and the
// conversions between geopotential and geometric height. Weather files give cloud bases and
// tops as pressures or geopotentials (GRIB2); the renderer needs metres above the ellipsoid.
#pragma once

namespace cloudsvc::weather {

// Constants of the standard atmosphere (ICAO Doc 7488/3, Table A and section 2).
inline constexpr double kStandardGravity_mps2 = 9.80665;      // g0
inline constexpr double kSeaLevelPressure_Pa = 101325.0;      // p0
inline constexpr double kSeaLevelTemperature_K = 288.15;      // T0
inline constexpr double kAirGasConstant_JpkgK = 287.05287;    // R, dry air
inline constexpr double kStandardEarthRadius_m = 6356766.0;   // r used for H <-> z

// Geopotential altitude H (geopotential metres) of pressure p (Pa) in the standard
// atmosphere: its three lowest layers, 0-11 km (lapse rate 6.5 K/km), 11-20 km (isothermal
// 216.65 K) and 20-32 km (-1 K/km), and the last one's formula beyond. Below sea level
// (p > p0) the lowest layer's formula continues. p <= 0 or non-finite gives NaN.
double standard_geopotential_altitude_m(double pressure_Pa);

// Geometric height z (m above mean sea level) of geopotential altitude H:
// z = r H / (r - H) with r = kStandardEarthRadius_m (ICAO Doc 7488/3, eq. 8).
double geometric_from_geopotential_m(double geopotential_altitude_m);

// Geometric height (m above mean sea level) at which the standard atmosphere has pressure p.
double standard_pressure_altitude_m(double pressure_Pa);

}  // namespace cloudsvc::weather
