// The soak clients' circling flight (soak_track.h).
#include "sim_client/soak_track.h"

#include <cmath>
#include <numbers>

#include "geodesy/geodetic.h"
#include "sim_client/angles.h"

namespace cloudsvc::sim {

namespace {
constexpr double kStandardGravity = 9.80665;  // m/s^2 (CGPM 1901)
constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr std::size_t kHeights = 8;  // clients share heights modulo this
}  // namespace

double SoakTrack::radius_m() const { return speed_mps / (turn_rate_deg_s * kRadPerDeg); }

protocol::Pose SoakTrack::pose(std::size_t client, double t_s) const {
  // Bearing of the aircraft from the centre, clockwise from north: it grows with time
  // (a right turn), and the heading is 90 deg ahead of it.
  const double bearing_deg = wrap_deg_360(phase_step_deg * static_cast<double>(client) + turn_rate_deg_s * t_s);
  const double b = bearing_deg * kRadPerDeg;
  const double r = radius_m();
  const glm::dvec3 offset_enu(r * std::sin(b), r * std::cos(b), 0.0);
  const glm::dvec3 centre = geo::geodetic_to_ecef({centre_lat_deg, centre_lon_deg, 0.0});
  const geo::Geodetic at = geo::ecef_to_geodetic(centre + geo::enu_to_ecef(centre_lat_deg, centre_lon_deg) * offset_enu);

  protocol::Pose p;
  p.sim_time_s = t_s;
  p.lat_deg = at.lat_deg;
  p.lon_deg = wrap_lon_deg(at.lon_deg);
  p.alt_m = base_alt_m + alt_step_m * static_cast<double>(client % kHeights);
  p.heading_deg = wrap_deg_360(bearing_deg + 90.0);
  p.pitch_deg = 0.0;
  p.roll_deg = std::atan(speed_mps * turn_rate_deg_s * kRadPerDeg / kStandardGravity) / kRadPerDeg;
  // Tangent of a clockwise circle at bearing b: east cos b, north -sin b.
  p.velocity_enu = protocol::VelocityEnu{speed_mps * std::cos(b), -speed_mps * std::sin(b), 0.0};
  return p;
}

}  // namespace cloudsvc::sim
