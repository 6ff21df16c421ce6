// Sun position: the NOAA Global Monitoring Laboratory solar calculator algorithm, i.e.
// the low-precision solar coordinates of Meeus, "Astronomical Algorithms" (2nd ed.),
// ch. 22 (obliquity), ch. 25 (solar coordinates, eqs. 25.2-25.8), ch. 28 (equation of
// time, Smart's formula 28.3), ch. 13 (horizontal coordinates), plus NOAA's piecewise
// refraction approximation. UT is used for TD (Delta T ~ 1 min shifts the Sun by
// ~0.0007 deg); no parallax (8.8 arcsec) or observer height.
#include "geodesy/solar_position.h"

#include <cmath>
#include <numbers>

namespace cloudsvc::geo {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double sind(double x) { return std::sin(x * kDeg); }
double cosd(double x) { return std::cos(x * kDeg); }
double tand(double x) { return std::tan(x * kDeg); }

// Reduces an angle in degrees to [0, 360).
double mod360(double x) {
  double r = std::fmod(x, 360.0);
  if (r < 0.0) r += 360.0;
  return r >= 360.0 ? 0.0 : r;
}

// NOAA refraction approximation (degrees) for a geometric elevation e (degrees):
// Bennett-like series above 5 deg, a polynomial fit between -0.575 and 5 deg, and a
// fading term below the horizon (arcseconds in the published formula, / 3600 here).
double noaa_refraction_deg(double e) {
  double arcsec = 0.0;
  if (e > 85.0) {
    arcsec = 0.0;
  } else if (e > 5.0) {
    const double t = tand(e);
    arcsec = 58.1 / t - 0.07 / (t * t * t) + 0.000086 / (t * t * t * t * t);
  } else if (e > -0.575) {
    arcsec = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  } else {
    arcsec = -20.772 / tand(e);
  }
  return arcsec / 3600.0;
}

}  // namespace

SolarPosition solar_position(double unix_time_s, double lat_deg, double lon_deg) {
  // Time. J2000.0 = 2000-01-01T12:00:00 = Unix 946728000 s. Subtracting first keeps the
  // Julian-century argument free of the cancellation JD - 2451545 would have.
  const double days_since_j2000 = (unix_time_s - 946728000.0) / 86400.0;
  const double T = days_since_j2000 / 36525.0;  // Julian centuries (UT used for TD)
  double sec_of_day = std::fmod(unix_time_s, 86400.0);
  if (sec_of_day < 0.0) sec_of_day += 86400.0;
  const double minutes_utc = sec_of_day / 60.0;

  // Meeus 25.2-25.4: geometric mean longitude L0, mean anomaly M, eccentricity e.
  const double L0 = mod360(280.46646 + T * (36000.76983 + T * 0.0003032));
  const double M = 357.52911 + T * (35999.05029 - 0.0001537 * T);
  const double e = 0.016708634 - T * (0.000042037 + 0.0000001267 * T);
  // Equation of the centre C, true longitude.
  const double C = sind(M) * (1.914602 - T * (0.004817 + 0.000014 * T)) +
                   sind(2.0 * M) * (0.019993 - 0.000101 * T) + sind(3.0 * M) * 0.000289;
  const double true_long = L0 + C;
  // Apparent longitude (low-precision nutation and aberration terms, Meeus ch. 25).
  const double omega = 125.04 - 1934.136 * T;
  const double lambda = true_long - 0.00569 - 0.00478 * sind(omega);
  // Mean obliquity (Meeus 22.2) and its correction for nutation (25.8).
  const double eps0 =
      23.0 + (26.0 + (21.448 - T * (46.815 + T * (0.00059 - T * 0.001813))) / 60.0) / 60.0;
  const double eps = eps0 + 0.00256 * cosd(omega);
  // Declination (25.7).
  const double decl = std::asin(sind(eps) * sind(lambda)) / kDeg;

  // Equation of time (Smart 1956, Meeus 28.3), minutes: apparent - mean solar time.
  const double y = tand(eps / 2.0) * tand(eps / 2.0);
  const double eot_rad = y * sind(2.0 * L0) - 2.0 * e * sind(M) +
                         4.0 * e * y * sind(M) * cosd(2.0 * L0) -
                         0.5 * y * y * sind(4.0 * L0) - 1.25 * e * e * sind(2.0 * M);
  const double eot_min = 4.0 * eot_rad / kDeg;

  // True solar time (minutes) and hour angle H (degrees, negative before noon).
  const double tst = std::fmod(minutes_utc + eot_min + 4.0 * lon_deg, 1440.0);
  const double H = std::remainder(tst / 4.0 - 180.0, 360.0);  // [-180, 180]

  // Horizontal coordinates from the unit vector (Meeus 13.5/13.6 written with atan2:
  // components in the local frame; no division by cos(lat) so the poles are fine).
  const double sphi = sind(lat_deg), cphi = cosd(lat_deg);
  const double sdec = sind(decl), cdec = cosd(decl);
  const double sH = sind(H), cH = cosd(H);
  const double up = sphi * sdec + cphi * cdec * cH;      // sin(elevation)
  const double west = cdec * sH;                         // towards west
  const double south = sphi * cdec * cH - cphi * sdec;   // towards south
  const double elevation = std::atan2(up, std::hypot(west, south)) / kDeg;
  // Meeus measures azimuth westward from south; +180 gives clockwise from north.
  const double azimuth = mod360(std::atan2(west, south) / kDeg + 180.0);

  SolarPosition out;
  out.azimuth_deg = azimuth;
  out.elevation_deg = elevation;
  out.apparent_elevation_deg = elevation + noaa_refraction_deg(elevation);
  out.declination_deg = decl;
  out.equation_of_time_min = eot_min;
  return out;
}

}  // namespace cloudsvc::geo
