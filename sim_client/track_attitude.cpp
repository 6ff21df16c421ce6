// Heading, flight-path pitch and coordinated-turn bank from a position track
// (method and limits in track_attitude.h).
#include "sim_client/track_attitude.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <GeographicLib/Geodesic.hpp>

#include "sim_client/angles.h"

namespace cloudsvc::sim {

namespace {

constexpr double kStandardGravity = 9.80665;  // m/s^2 (CGPM 1901)
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// Chord velocity of sample i: course (deg), ground speed and vertical speed (m/s).
struct ChordMotion {
  double course_deg = 0.0;
  double ground_speed = 0.0;
  double vertical_speed = 0.0;
};

ChordMotion chord_motion(const std::vector<PoseSample>& s, std::size_t i, double half_window) {
  const std::size_t n = s.size();
  const double ti = s[i].unix_time_s;
  std::size_t j0 = i > 0 ? i - 1 : i;
  while (j0 > 0 && ti - s[j0 - 1].unix_time_s <= half_window) --j0;
  std::size_t j1 = i + 1 < n ? i + 1 : i;
  while (j1 + 1 < n && s[j1 + 1].unix_time_s - ti <= half_window) ++j1;

  const geo::Geodetic& a = s[j0].position;
  const geo::Geodetic& b = s[j1].position;
  const double dt = s[j1].unix_time_s - s[j0].unix_time_s;  // > 0: n >= 2, times increase
  double dist = 0.0, azi1 = 0.0, azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(a.lat_deg, a.lon_deg, b.lat_deg, b.lon_deg, dist,
                                           azi1, azi2);
  // Circular mean of the azimuths at both ends (they differ by the meridian convergence).
  const double y = std::sin(azi1 / kDegPerRad) + std::sin(azi2 / kDegPerRad);
  const double x = std::cos(azi1 / kDegPerRad) + std::cos(azi2 / kDegPerRad);
  ChordMotion m;
  m.course_deg = wrap_deg_360(std::atan2(y, x) * kDegPerRad);
  // Samples under ~1e-300 s apart (only near the epoch: an ACMI ReferenceTime of
  // 1970-01-01 with frames #0 and #1e-320) overflow the speeds to inf, which made the
  // velocity (inf * sin 0) and the bank (atan(inf * 0)) NaN: keep them finite.
  constexpr double kMaxSpeed = std::numeric_limits<double>::max();
  m.ground_speed = std::min(dist / dt, kMaxSpeed);
  m.vertical_speed = std::clamp((b.alt_m - a.alt_m) / dt, -kMaxSpeed, kMaxSpeed);
  return m;
}

}  // namespace

void derive_attitude_from_track(std::vector<PoseSample>& samples,
                                const DerivedAttitudeParams& params) {
  const std::size_t n = samples.size();
  if (n == 0) return;
  if (n == 1) {
    samples[0].attitude = {};
    samples[0].velocity_enu_mps.reset();
    return;
  }

  std::vector<ChordMotion> motion(n);
  std::vector<bool> moving(n);
  for (std::size_t i = 0; i < n; ++i) {
    motion[i] = chord_motion(samples, i, params.half_window_s);
    moving[i] = motion[i].ground_speed >= params.min_speed_mps;
  }

  // Heading: course while moving; held through slow stretches, back-filled at the start.
  std::vector<double> heading(n, 0.0);
  const auto first_moving = std::find(moving.begin(), moving.end(), true);
  double held = first_moving == moving.end()
                    ? 0.0
                    : motion[static_cast<std::size_t>(first_moving - moving.begin())].course_deg;
  for (std::size_t i = 0; i < n; ++i) {
    if (moving[i]) held = motion[i].course_deg;
    heading[i] = held;
  }

  for (std::size_t i = 0; i < n; ++i) {
    const ChordMotion& m = motion[i];
    PoseSample& s = samples[i];
    const double course_rad = m.course_deg / kDegPerRad;
    s.velocity_enu_mps = glm::dvec3(m.ground_speed * std::sin(course_rad),
                                    m.ground_speed * std::cos(course_rad), m.vertical_speed);
    s.attitude.heading_deg = heading[i];
    s.attitude.pitch_deg =
        moving[i] ? std::clamp(std::atan2(m.vertical_speed, m.ground_speed) * kDegPerRad,
                               -params.max_pitch_deg, params.max_pitch_deg)
                  : 0.0;

    const std::size_t k0 = i > 0 ? i - 1 : i;
    const std::size_t k1 = i + 1 < n ? i + 1 : i;
    double bank = 0.0;
    if (moving[i] && moving[k0] && moving[k1]) {
      const double dt = samples[k1].unix_time_s - samples[k0].unix_time_s;
      const double omega = wrap_deg_180(heading[k1] - heading[k0]) / kDegPerRad / dt;  // rad/s
      bank = std::atan(m.ground_speed * omega / kStandardGravity) * kDegPerRad;
      bank = std::clamp(bank, -params.max_bank_deg, params.max_bank_deg);
    }
    s.attitude.roll_deg = bank;
  }
}

}  // namespace cloudsvc::sim
