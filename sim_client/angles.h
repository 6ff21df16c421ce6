// Angle wrapping in degrees, shared by the flight-log readers, pose interpolation and
// attitude derivation.
#pragma once

#include <cmath>

namespace cloudsvc::sim {

// a wrapped into [0, 360).
inline double wrap_deg_360(double a) {
  double r = std::fmod(a, 360.0);
  if (r < 0.0) r += 360.0;
  if (r >= 360.0) r -= 360.0;  // -1e-17 + 360 rounds to 360
  return r;
}

// a wrapped into [-180, 180): the signed shortest turn for a difference of angles.
inline double wrap_deg_180(double a) { return wrap_deg_360(a + 180.0) - 180.0; }

// A longitude in degrees wrapped into [-180, 180) (180 becomes -180). A value already in
// that range is returned unchanged, bit for bit (wrap_deg_180 adds and subtracts 180,
// which would round away its low bits).
inline double wrap_lon_deg(double lon) {
  if (lon >= -180.0 && lon < 180.0) return lon;
  return wrap_deg_180(lon);
}

}  // namespace cloudsvc::sim
