// Geodetic <-> Earth-centred conversions and local frames on the WGS84 ellipsoid.
// All in double precision. Altitudes are metres above the WGS84
// ellipsoid; angles are degrees unless a name says _rad.
#pragma once

#include <glm/glm.hpp>

namespace cloudsvc::geo {

// A position on or above the WGS84 ellipsoid.
struct Geodetic {
  double lat_deg = 0.0;  // geodetic latitude, [-90, 90]
  double lon_deg = 0.0;  // longitude, east positive (any value; normalised on use)
  double alt_m = 0.0;    // height above the ellipsoid, m
};

// Aircraft attitude, aviation convention.
struct Attitude {
  double heading_deg = 0.0;  // true heading, clockwise from true north
  double pitch_deg = 0.0;    // nose up positive, [-90, 90]
  double roll_deg = 0.0;     // right wing down positive
};

// Earth-centred, Earth-fixed (ECEF) position in metres (GeographicLib::Geocentric::WGS84).
glm::dvec3 geodetic_to_ecef(const Geodetic& g);
Geodetic ecef_to_geodetic(const glm::dvec3& ecef);

// Rotation whose columns are the local East, North, Up unit vectors expressed in ECEF,
// at a geodetic latitude/longitude (Up = ellipsoid normal). Multiply an ENU vector by it
// to get the ECEF vector.
glm::dmat3 enu_to_ecef(double lat_deg, double lon_deg);

// Body axes of an aircraft with the given attitude, expressed in the local ENU frame.
// forward = nose direction, right = right wing, up = canopy (right-handed: up = right x forward).
struct BodyAxes {
  glm::dvec3 forward;
  glm::dvec3 right;
  glm::dvec3 up;
};
BodyAxes body_axes_enu(const Attitude& a);
// The attitude of body axes given in the local ENU frame: the inverse of body_axes_enu
// (heading in [0, 360)). Looking straight up or down, the heading is that of the right axis
// and the roll 0.
Attitude attitude_of(const BodyAxes& axes);

// WGS84 radii of curvature at a geodetic latitude, metres.
double meridional_radius(double lat_deg);      // M
double prime_vertical_radius(double lat_deg);  // N
// Radius of the osculating (Gaussian mean curvature) sphere sqrt(M*N): the sphere that
// best matches the ellipsoid around the camera. Used as the cloud-shell radius.
double gaussian_radius(double lat_deg);

// Wraps a longitude into [-180, 180).
double wrap_longitude_deg(double lon_deg);

}  // namespace cloudsvc::geo
