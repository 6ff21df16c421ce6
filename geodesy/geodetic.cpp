// WGS84 geodetic <-> ECEF conversions, local ENU frames, aircraft body axes and radii
// of curvature. Everything in double. Angles in degrees, lengths in
// metres. Conversions go through GeographicLib::Geocentric::WGS84() (Karney 2011,
// accurate to a few nm); trigonometry of degree arguments uses Math::sincosd so that
// multiples of 90 deg give exact 0/±1 (exact frames at the poles and meridians).
#include "geodesy/geodetic.h"

#include <algorithm>
#include <cmath>

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Math.hpp>

namespace cloudsvc::geo {

namespace {

using GeographicLib::Math;

// First eccentricity squared of WGS84, e^2 = f (2 - f).
double wgs84_e2() {
  const double f = GeographicLib::Constants::WGS84_f();
  return f * (2.0 - f);
}

// 1 - e^2 sin^2(phi), the common factor of the radii of curvature.
double radius_denominator(double lat_deg) {
  double s = 0.0, c = 0.0;
  Math::sincosd(lat_deg, s, c);
  return 1.0 - wgs84_e2() * s * s;
}

}  // namespace

glm::dvec3 geodetic_to_ecef(const Geodetic& g) {
  double x = 0.0, y = 0.0, z = 0.0;
  GeographicLib::Geocentric::WGS84().Forward(g.lat_deg, g.lon_deg, g.alt_m, x, y, z);
  return {x, y, z};
}

Geodetic ecef_to_geodetic(const glm::dvec3& ecef) {
  Geodetic g;
  // Longitude comes back in [-180, 180]; at the poles it is 0 (arbitrary there).
  GeographicLib::Geocentric::WGS84().Reverse(ecef.x, ecef.y, ecef.z, g.lat_deg, g.lon_deg,
                                              g.alt_m);
  return g;
}

glm::dmat3 enu_to_ecef(double lat_deg, double lon_deg) {
  double sphi = 0.0, cphi = 0.0, slam = 0.0, clam = 0.0;
  Math::sincosd(lat_deg, sphi, cphi);
  Math::sincosd(lon_deg, slam, clam);
  // Columns: East, North, Up (the ellipsoid normal at geodetic latitude phi).
  const glm::dvec3 east(-slam, clam, 0.0);
  const glm::dvec3 north(-sphi * clam, -sphi * slam, cphi);
  const glm::dvec3 up(cphi * clam, cphi * slam, sphi);
  return glm::dmat3(east, north, up);  // glm: each argument is a column
}

// Standard aerospace 3-2-1 Euler sequence (yaw psi = heading, then pitch theta about the
// new right axis, then roll phi about the new forward axis). In NED coordinates the
// body->NED matrix is C = Rz(psi) Ry(theta) Rx(phi) with body axes x forward, y right,
// z down; its columns are the body axes in NED. ENU components follow from
// E = NED.y, N = NED.x, U = -NED.z, and body up = -z_body.
BodyAxes body_axes_enu(const Attitude& a) {
  double sy = 0.0, cy = 0.0, sp = 0.0, cp = 0.0, sr = 0.0, cr = 0.0;
  Math::sincosd(a.heading_deg, sy, cy);
  Math::sincosd(a.pitch_deg, sp, cp);
  Math::sincosd(a.roll_deg, sr, cr);

  BodyAxes b;
  // x_body in NED = (cp cy, cp sy, -sp)
  b.forward = glm::dvec3(cp * sy, cp * cy, sp);
  // y_body in NED = (sr sp cy - cr sy, sr sp sy + cr cy, sr cp)
  b.right = glm::dvec3(sr * sp * sy + cr * cy, sr * sp * cy - cr * sy, -sr * cp);
  // z_body in NED = (cr sp cy + sr sy, cr sp sy - sr cy, cr cp); up = -z_body
  b.up = glm::dvec3(-(cr * sp * sy - sr * cy), -(cr * sp * cy + sr * sy), cr * cp);
  return b;
}

Attitude attitude_of(const BodyAxes& a) {
  const double kDeg = 180.0 / Math::pi();
  Attitude out;
  out.pitch_deg = std::asin(std::clamp(a.forward.z, -1.0, 1.0)) * kDeg;
  if (std::hypot(a.forward.x, a.forward.y) > 1e-9) {
    out.heading_deg = std::atan2(a.forward.x, a.forward.y) * kDeg;
    // right.z = -sin(roll) cos(pitch), up.z = cos(roll) cos(pitch) (body_axes_enu)
    out.roll_deg = std::atan2(-a.right.z, a.up.z) * kDeg;
  } else {  // straight up or down: heading and roll turn about the same axis; roll 0
    out.heading_deg = std::atan2(-a.right.y, a.right.x) * kDeg;
  }
  if (out.heading_deg < 0.0) out.heading_deg += 360.0;
  return out;
}

// Radii of curvature of the WGS84 ellipsoid (e.g. Torge & Müller, Geodesy, §4.1):
//   M = a (1 - e^2) / (1 - e^2 sin^2 phi)^{3/2},  N = a / (1 - e^2 sin^2 phi)^{1/2}.
double meridional_radius(double lat_deg) {
  const double a = GeographicLib::Constants::WGS84_a();
  const double w = radius_denominator(lat_deg);
  return a * (1.0 - wgs84_e2()) / (w * std::sqrt(w));
}

double prime_vertical_radius(double lat_deg) {
  const double a = GeographicLib::Constants::WGS84_a();
  return a / std::sqrt(radius_denominator(lat_deg));
}

// sqrt(M N) = a sqrt(1 - e^2) / (1 - e^2 sin^2 phi) = b / (1 - e^2 sin^2 phi), b = a sqrt(1 - e^2).
double gaussian_radius(double lat_deg) {
  const double a = GeographicLib::Constants::WGS84_a();
  return a * std::sqrt(1.0 - wgs84_e2()) / radius_denominator(lat_deg);
}

double wrap_longitude_deg(double lon_deg) {
  // std::remainder is exact and returns a value in [-180, 180]; fold +180 to -180.
  // Unlike fmod(lon + 180, 360) - 180 it does not round tiny longitudes to 0.
  double r = std::remainder(lon_deg, 360.0);
  if (r >= 180.0) r -= 360.0;
  return r;
}

}  // namespace cloudsvc::geo
