// Attitude derived from a position track: heading from the geodesic chord, flight-path
// pitch, coordinated-turn bank tan(phi) = V omega / g.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <GeographicLib/Geodesic.hpp>

#include "sim_client/angles.h"
#include "sim_client/track_attitude.h"

namespace {

using cloudsvc::sim::derive_attitude_from_track;
using cloudsvc::sim::PoseSample;
using cloudsvc::sim::wrap_deg_180;

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kG = 9.80665;

// Point at `distance` m along azimuth `azimuth_deg` from (lat, lon).
PoseSample at_offset(double t, double lat, double lon, double azimuth_deg, double distance,
                     double alt) {
  PoseSample s;
  s.unix_time_s = t;
  GeographicLib::Geodesic::WGS84().Direct(lat, lon, azimuth_deg, distance, s.position.lat_deg,
                                          s.position.lon_deg);
  s.position.alt_m = alt;
  return s;
}

// Circle of radius r around (lat, lon) flown at speed v, clockwise (right turn) when
// right_turn, one fix every dt seconds for `duration`.
std::vector<PoseSample> circle(double lat, double lon, double r, double v, bool right_turn,
                               double dt, double duration) {
  std::vector<PoseSample> out;
  const double omega_deg = v / r * kDegPerRad * (right_turn ? 1.0 : -1.0);
  for (double t = 0.0; t <= duration + 1e-9; t += dt)
    out.push_back(at_offset(1.6e9 + t, lat, lon, omega_deg * t, r, 1500.0));
  return out;
}

void expect_circle(bool right_turn, double dt) {
  const double r = 300.0, v = 30.0;
  std::vector<PoseSample> track = circle(47.0, 8.0, r, v, right_turn, dt, 120.0);
  derive_attitude_from_track(track);
  // Right turn: velocity azimuth = radial azimuth + 90; left turn: - 90.
  const double omega_deg = v / r * kDegPerRad * (right_turn ? 1.0 : -1.0);
  const double expected_bank =
      std::atan(v * (v / r) / kG) * kDegPerRad * (right_turn ? 1.0 : -1.0);  // 17.0 deg
  for (std::size_t i = 3; i + 3 < track.size(); ++i) {
    const PoseSample& s = track[i];
    const double t = s.unix_time_s - 1.6e9;
    const double expected_heading = omega_deg * t + (right_turn ? 90.0 : -90.0);
    SCOPED_TRACE(testing::Message() << "t " << t);
    EXPECT_NEAR(wrap_deg_180(s.attitude.heading_deg - expected_heading), 0.0, 0.5);
    EXPECT_NEAR(s.attitude.roll_deg, expected_bank, dt > 1.5 ? 1.5 : 0.5);
    EXPECT_NEAR(s.attitude.pitch_deg, 0.0, 1e-6);
    ASSERT_TRUE(s.velocity_enu_mps.has_value());
    EXPECT_NEAR(std::hypot(s.velocity_enu_mps->x, s.velocity_enu_mps->y), v, 0.05 * v);
  }
}

TEST(TrackAttitude, RightTurnBanksRight) { expect_circle(true, 1.0); }
TEST(TrackAttitude, LeftTurnBanksLeft) { expect_circle(false, 1.0); }
TEST(TrackAttitude, SparseFixesStillFollowTheTurn) { expect_circle(true, 3.0); }

TEST(TrackAttitude, StraightClimbGivesFlightPathPitch) {
  std::vector<PoseSample> track;
  for (int k = 0; k <= 20; ++k)  // 20 m/s on azimuth 30, climbing 2 m/s
    track.push_back(at_offset(100.0 + k, -38.0, 176.0, 30.0, 20.0 * k, 500.0 + 2.0 * k));
  derive_attitude_from_track(track);
  for (const PoseSample& s : track) {
    EXPECT_NEAR(s.attitude.heading_deg, 30.0, 0.01);
    EXPECT_NEAR(s.attitude.pitch_deg, std::atan(0.1) * kDegPerRad, 0.01);  // 5.71 deg
    EXPECT_NEAR(s.attitude.roll_deg, 0.0, 0.01);
    EXPECT_NEAR(s.velocity_enu_mps->z, 2.0, 1e-6);
    EXPECT_NEAR(s.velocity_enu_mps->x, 20.0 * std::sin(30.0 / kDegPerRad), 0.01);
    EXPECT_NEAR(s.velocity_enu_mps->y, 20.0 * std::cos(30.0 / kDegPerRad), 0.01);
  }
}

TEST(TrackAttitude, EastboundAcrossTheAntimeridian) {
  std::vector<PoseSample> track;
  for (int k = 0; k <= 10; ++k) {
    PoseSample s = at_offset(k, 0.0, 179.999, 90.0, 50.0 * k, 1000.0);
    track.push_back(s);
  }
  ASSERT_LT(track.back().position.lon_deg, 0.0);  // crossed
  derive_attitude_from_track(track);
  for (const PoseSample& s : track) {
    EXPECT_NEAR(s.attitude.heading_deg, 90.0, 0.01);
    EXPECT_NEAR(s.velocity_enu_mps->x, 50.0, 0.01);
  }
}

TEST(TrackAttitude, HoldsHeadingWhenStationary) {
  std::vector<PoseSample> track;
  for (int k = 0; k < 5; ++k) track.push_back(at_offset(k, 45.0, 13.0, 0.0, 0.0, 100.0));
  for (int k = 1; k <= 10; ++k)
    track.push_back(at_offset(4 + k, 45.0, 13.0, 200.0, 15.0 * k, 100.0 + 5.0 * k));
  const PoseSample last = track.back();
  for (int k = 1; k <= 5; ++k) {  // stopped again (altitude noise must not pitch it up)
    PoseSample s = last;
    s.unix_time_s += k;
    s.position.alt_m += (k % 2) * 0.5;
    track.push_back(s);
  }
  derive_attitude_from_track(track);
  for (const PoseSample& s : track) EXPECT_NEAR(s.attitude.heading_deg, 200.0, 0.01);
  EXPECT_DOUBLE_EQ(track[0].attitude.pitch_deg, 0.0);
  EXPECT_DOUBLE_EQ(track[0].attitude.roll_deg, 0.0);
  EXPECT_DOUBLE_EQ(track.back().attitude.pitch_deg, 0.0);
  EXPECT_GT(track[9].attitude.pitch_deg, 15.0);  // 5 m/s up at 15 m/s: 18.4 deg
}

TEST(TrackAttitude, ClampsBankAndPitch) {
  // 10 m radius at 40 m/s: tan(phi) = 16.3 -> 86.5 deg, clamped to 75.
  // Chord over the neighbouring fixes only: a wider window would wrap around the circle.
  cloudsvc::sim::DerivedAttitudeParams neighbours;
  neighbours.half_window_s = 0.0;
  std::vector<PoseSample> track = circle(10.0, 10.0, 10.0, 40.0, true, 0.05, 3.0);
  derive_attitude_from_track(track, neighbours);
  EXPECT_DOUBLE_EQ(track[10].attitude.roll_deg, 75.0);
  // Climbing 10 m/s at 2 m/s over ground: 78.7 deg, clamped to 45.
  std::vector<PoseSample> steep;
  for (int k = 0; k <= 5; ++k) steep.push_back(at_offset(k, 0.0, 0.0, 0.0, 2.0 * k, 10.0 * k));
  derive_attitude_from_track(steep);
  EXPECT_DOUBLE_EQ(steep[2].attitude.pitch_deg, 45.0);
}

// Found with the track check of fuzz/simclient_acmi_fuzz.cpp, on a constructed input: an
// ACMI file with ReferenceTime 1970-01-01T00:00:00Z and frames #0 and #1e-320 gives samples
// 1e-320 s apart; the chord speed overflowed to inf, so velocity (inf * sin 0) and bank
// (atan(inf * 0)) were NaN.
// Whatever the spacing, the derived values stay finite (replay then refuses the absurd
// speed with a message instead of sending NaN).
TEST(TrackAttitude, SamplesCloserThanAnySpeedStayFinite) {
  std::vector<PoseSample> track = {at_offset(0.0, 0.0, 0.0, 0.0, 0.0, 100.0),
                                   at_offset(1e-320, 0.0, 0.0, 0.0, 110000.0, 300.0),
                                   at_offset(2e-320, 0.0, 0.0, 90.0, 110000.0, 100.0)};
  derive_attitude_from_track(track);
  for (const PoseSample& s : track) {
    EXPECT_TRUE(std::isfinite(s.attitude.heading_deg) && std::isfinite(s.attitude.pitch_deg) &&
                std::isfinite(s.attitude.roll_deg))
        << s.attitude.heading_deg << " " << s.attitude.pitch_deg << " " << s.attitude.roll_deg;
    ASSERT_TRUE(s.velocity_enu_mps.has_value());
    EXPECT_TRUE(std::isfinite(s.velocity_enu_mps->x) && std::isfinite(s.velocity_enu_mps->y) &&
                std::isfinite(s.velocity_enu_mps->z));
  }
}

TEST(TrackAttitude, SingleSampleHasNoVelocity) {
  std::vector<PoseSample> one = {at_offset(0.0, 1.0, 2.0, 0.0, 0.0, 3.0)};
  one[0].attitude.heading_deg = 123.0;
  one[0].velocity_enu_mps = glm::dvec3(1.0);
  derive_attitude_from_track(one);
  EXPECT_DOUBLE_EQ(one[0].attitude.heading_deg, 0.0);
  EXPECT_FALSE(one[0].velocity_enu_mps.has_value());
}

}  // namespace
