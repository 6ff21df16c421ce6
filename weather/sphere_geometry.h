// Positions on the Earth taken as a sphere of its mean radius, for distances and offsets
// between weather data points (forecast regions, aerodromes, a service's poses); kilometre
// accuracy is all they need (the geodesy module does the precise WGS84 work).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace cloudsvc::weather {

inline constexpr double kMeanEarthRadius_m = 6371008.8;  // IUGG mean radius R1
inline constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

// Unit vector from the centre towards latitude / longitude (degrees).
inline std::array<double, 3> unit_vector(double lat_deg, double lon_deg) {
  const double p = lat_deg * kRadPerDeg, l = lon_deg * kRadPerDeg;
  return {std::cos(p) * std::cos(l), std::cos(p) * std::sin(l), std::sin(p)};
}

// Angle (rad) between two unit vectors, from their chord: accurate at small angles.
inline double arc_between(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double chord = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  return 2.0 * std::asin(std::min(1.0, chord / 2.0));
}

// Great-circle distance (m) between two positions (degrees).
inline double surface_distance_m(double lat1, double lon1, double lat2, double lon2) {
  return kMeanEarthRadius_m * arc_between(unit_vector(lat1, lon1), unit_vector(lat2, lon2));
}

}  // namespace cloudsvc::weather
