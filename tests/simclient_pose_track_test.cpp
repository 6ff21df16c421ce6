// PoseTrack::at (ECEF-chord position, shortest-arc angles, velocity) and resample(fps).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <GeographicLib/Geodesic.hpp>

#include "sim_client/pose_track.h"
#include "sim_client/replay_poses.h"

namespace {

using cloudsvc::geo::Attitude;
using cloudsvc::geo::Geodetic;
using cloudsvc::sim::PoseSample;
using cloudsvc::sim::PoseTrack;
using cloudsvc::sim::resample;

PoseSample sample(double t, double lat, double lon, double alt, Attitude att = {}) {
  PoseSample s;
  s.unix_time_s = t;
  s.position = {lat, lon, alt};
  s.attitude = att;
  return s;
}

// Geodesic distance on WGS84, m.
double distance_m(const Geodetic& a, const Geodetic& b) {
  double s = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(a.lat_deg, a.lon_deg, b.lat_deg, b.lon_deg, s);
  return s;
}

// Every interpolated point between two samples lies on the short path: its distances to
// both ends add up to the end-to-end distance (within tol) and grow monotonically.
void expect_short_path(const PoseTrack& track, double tol_m) {
  const Geodetic& a = track.samples.front().position;
  const Geodetic& b = track.samples.back().position;
  const double total = distance_m(a, b);
  double previous = -1.0;
  for (int k = 0; k <= 100; ++k) {
    const double t = track.start_time() + (track.end_time() - track.start_time()) * k / 100.0;
    const Geodetic p = track.at(t).position;
    SCOPED_TRACE(testing::Message() << "k " << k << " lat " << p.lat_deg << " lon " << p.lon_deg);
    const double from_a = distance_m(a, p);
    EXPECT_NEAR(from_a + distance_m(p, b), total, tol_m);
    EXPECT_GE(from_a, previous - 1e-6);
    previous = from_a;
  }
}

TEST(PoseTrackAt, ExactAtSamplesAndLinearInTime) {
  PoseTrack track;
  track.samples = {sample(100.0, 47.0, 8.0, 1000.0, {10.0, 2.0, -5.0}),
                   sample(110.0, 47.001, 8.002, 2000.0, {30.0, 6.0, 15.0})};
  const PoseSample a = track.at(100.0);
  EXPECT_NEAR(a.position.lat_deg, 47.0, 1e-10);
  EXPECT_NEAR(a.position.lon_deg, 8.0, 1e-10);
  EXPECT_NEAR(a.position.alt_m, 1000.0, 1e-9);
  const PoseSample m = track.at(102.5);
  EXPECT_DOUBLE_EQ(m.unix_time_s, 102.5);
  EXPECT_NEAR(m.position.lat_deg, 47.00025, 1e-8);
  EXPECT_NEAR(m.position.lon_deg, 8.0005, 1e-8);
  EXPECT_NEAR(m.position.alt_m, 1250.0, 1e-9);
  EXPECT_NEAR(m.attitude.heading_deg, 15.0, 1e-12);
  EXPECT_NEAR(m.attitude.pitch_deg, 3.0, 1e-12);
  EXPECT_NEAR(m.attitude.roll_deg, 0.0, 1e-12);
  const PoseSample b = track.at(110.0);
  EXPECT_NEAR(b.position.lat_deg, 47.001, 1e-10);
  EXPECT_NEAR(b.attitude.heading_deg, 30.0, 1e-12);
}

TEST(PoseTrackAt, HeightDoesNotSagOnLongChords) {
  // 10 degrees of longitude apart: the straight ECEF chord dips ~9.7 km below the surface
  // midway; the interpolated height must still be the linear mean.
  PoseTrack track;
  track.samples = {sample(0.0, 0.0, 0.0, 3000.0), sample(10.0, 0.0, 10.0, 5000.0)};
  const PoseSample m = track.at(5.0);
  EXPECT_NEAR(m.position.alt_m, 4000.0, 1e-6);
  EXPECT_NEAR(m.position.lon_deg, 5.0, 1e-9);
  EXPECT_NEAR(m.position.lat_deg, 0.0, 1e-9);
}

TEST(PoseTrackAt, AntimeridianTakesTheShortWay) {
  PoseTrack track;
  track.samples = {sample(0.0, -16.5, 179.99, 1000.0), sample(10.0, -16.5, -179.99, 1000.0)};
  const PoseSample m = track.at(5.0);
  EXPECT_NEAR(std::fabs(m.position.lon_deg), 180.0, 1e-7);
  EXPECT_NEAR(m.position.lat_deg, -16.5, 1e-6);
  for (int k = 0; k <= 10; ++k) {
    const double lon = track.at(k).position.lon_deg;
    EXPECT_GE(std::fabs(lon), 179.99 - 1e-9) << "t " << k << ": went the long way, lon " << lon;
  }
  expect_short_path(track, 0.05);
}

// Longitudes come out in [-180, 180), the readers' range: the point of the chord right on
// the antimeridian is -180, not +180 (GeographicLib returns +180 for it).
TEST(PoseTrackAt, AntimeridianPointsAreInTheHalfOpenRange) {
  PoseTrack track;
  track.samples = {sample(0.0, 0.0, 179.9, 1000.0), sample(10.0, 0.0, -179.9, 1000.0)};
  for (int k = 0; k <= 20; ++k) {
    const double lon = track.at(0.5 * k).position.lon_deg;
    SCOPED_TRACE(testing::Message() << "t " << 0.5 * k << " lon " << lon);
    EXPECT_GE(lon, -180.0);
    EXPECT_LT(lon, 180.0);
    EXPECT_GE(std::fabs(lon), 179.9 - 1e-9) << "went the long way round";
  }
  EXPECT_NEAR(std::fabs(track.at(5.0).position.lon_deg), 180.0, 1e-9);
}

TEST(PoseTrackAt, OverThePoleTakesTheShortWay) {
  // 89.99 N on opposite meridians: 2.2 km apart across the pole, 20000 km the other way.
  PoseTrack track;
  track.samples = {sample(0.0, 89.99, 0.0, 500.0), sample(20.0, 89.99, 180.0, 500.0)};
  EXPECT_GT(track.at(10.0).position.lat_deg, 89.9999);
  for (int k = 0; k <= 20; ++k)
    EXPECT_GE(track.at(k).position.lat_deg, 89.99 - 1e-9) << "t " << k;
  expect_short_path(track, 0.05);
}

TEST(PoseTrackAt, NearThePoleStaysOnTheShortPath) {
  // 89.9 S, 100 degrees of longitude apart: the short path curves around the pole.
  PoseTrack track;
  track.samples = {sample(0.0, -89.9, 10.0, 0.0), sample(60.0, -89.9, 110.0, 0.0)};
  for (int k = 0; k <= 60; ++k)
    EXPECT_LE(track.at(k).position.lat_deg, -89.9 + 1e-9) << "t " << k;
  expect_short_path(track, 0.05);
}

TEST(PoseTrackAt, AnglesTakeTheShortestArc) {
  PoseTrack track;
  track.samples = {sample(0.0, 10.0, 10.0, 0.0, {350.0, -10.0, 170.0}),
                   sample(4.0, 10.0, 10.0, 0.0, {10.0, 10.0, -170.0})};
  const PoseSample q = track.at(1.0);
  EXPECT_NEAR(q.attitude.heading_deg, 355.0, 1e-9);
  EXPECT_NEAR(q.attitude.roll_deg, 175.0, 1e-9);
  EXPECT_NEAR(q.attitude.pitch_deg, -5.0, 1e-12);
  const PoseSample m = track.at(2.0);
  EXPECT_NEAR(m.attitude.heading_deg, 0.0, 1e-9);
  EXPECT_NEAR(std::fabs(m.attitude.roll_deg), 180.0, 1e-9);
  const PoseSample r = track.at(3.0);
  EXPECT_NEAR(r.attitude.heading_deg, 5.0, 1e-9);
  EXPECT_NEAR(r.attitude.roll_deg, -175.0, 1e-9);
  for (double t = 0.0; t <= 4.0; t += 0.125) {
    const PoseSample s = track.at(t);
    EXPECT_GE(s.attitude.heading_deg, 0.0);
    EXPECT_LT(s.attitude.heading_deg, 360.0);
    EXPECT_GE(s.attitude.roll_deg, -180.0);
    EXPECT_LT(s.attitude.roll_deg, 180.0);
  }
}

TEST(PoseTrackAt, VelocityInterpolatedInTheLocalFrame) {
  PoseTrack track;
  track.samples = {sample(0.0, 30.0, 179.999, 0.0), sample(2.0, 30.0, -179.999, 0.0)};
  track.samples[0].velocity_enu_mps = glm::dvec3(96.0, 0.0, 2.0);
  track.samples[1].velocity_enu_mps = glm::dvec3(100.0, 0.0, 4.0);
  const PoseSample m = track.at(1.0);
  ASSERT_TRUE(m.velocity_enu_mps.has_value());
  EXPECT_NEAR(m.velocity_enu_mps->x, 98.0, 1e-3);
  EXPECT_NEAR(m.velocity_enu_mps->y, 0.0, 1e-3);
  EXPECT_NEAR(m.velocity_enu_mps->z, 3.0, 1e-3);
  track.samples[1].velocity_enu_mps.reset();
  EXPECT_FALSE(track.at(1.0).velocity_enu_mps.has_value());
}

TEST(PoseTrackAt, HoldsTheEndSamplesOutsideTheTrack) {
  PoseTrack track;
  track.samples = {sample(10.0, 1.0, 2.0, 3.0, {40.0, 1.0, 2.0}),
                   sample(20.0, 4.0, 5.0, 6.0, {50.0, 3.0, 4.0})};
  const PoseSample before = track.at(0.0);
  EXPECT_DOUBLE_EQ(before.unix_time_s, 0.0);
  EXPECT_DOUBLE_EQ(before.position.lat_deg, 1.0);
  EXPECT_DOUBLE_EQ(before.attitude.heading_deg, 40.0);
  const PoseSample after = track.at(99.0);
  EXPECT_DOUBLE_EQ(after.unix_time_s, 99.0);
  EXPECT_DOUBLE_EQ(after.position.alt_m, 6.0);
  EXPECT_DOUBLE_EQ(after.attitude.roll_deg, 4.0);

  PoseTrack single;
  single.samples = {sample(5.0, 7.0, 8.0, 9.0)};
  EXPECT_DOUBLE_EQ(single.at(100.0).position.lon_deg, 8.0);
}

TEST(PoseTrackAt, RejectsEmptyTrackAndNonFiniteTime) {
  PoseTrack empty;
  EXPECT_THROW(empty.at(0.0), std::out_of_range);
  PoseTrack track;
  track.samples = {sample(0.0, 0.0, 0.0, 0.0), sample(1.0, 0.0, 0.0, 0.0)};
  EXPECT_THROW(track.at(std::nan("")), std::invalid_argument);
  EXPECT_THROW(track.at(INFINITY), std::invalid_argument);
}

TEST(Resample, CountAndMonotonicTimes) {
  PoseTrack track;
  const double t0 = 1.7e9;  // realistic Unix times: k / fps must not drift or repeat
  track.samples = {sample(t0, 47.0, 8.0, 0.0), sample(t0 + 4.0, 47.01, 8.0, 100.0),
                   sample(t0 + 10.0, 47.02, 8.01, 50.0)};
  const auto frames = resample(track, 30.0);
  ASSERT_EQ(frames.size(), 301u);  // 10 s * 30 fps + the first frame
  EXPECT_DOUBLE_EQ(frames.front().unix_time_s, t0);
  EXPECT_NEAR(frames.back().unix_time_s, t0 + 10.0, 1e-6);
  for (std::size_t k = 1; k < frames.size(); ++k) {
    EXPECT_GT(frames[k].unix_time_s, frames[k - 1].unix_time_s) << k;
    EXPECT_NEAR(frames[k].unix_time_s - frames[k - 1].unix_time_s, 1.0 / 30.0, 1e-6) << k;
  }
  // Frame 120 is the middle sample exactly.
  EXPECT_NEAR(frames[120].position.lat_deg, 47.01, 1e-9);
  EXPECT_NEAR(frames[120].position.alt_m, 100.0, 1e-6);

  EXPECT_EQ(resample(track, 7.0).size(), 71u);
  EXPECT_EQ(resample(track, 0.25).size(), 3u);   // 0, 4, 8 s
  EXPECT_EQ(resample(track, 0.05).size(), 1u);   // one frame every 20 s
  EXPECT_EQ(resample(track, 2.95).size(), 30u);  // floor(29.5) + 1
  const auto odd = resample(track, 2.95);
  EXPECT_LE(odd.back().unix_time_s, t0 + 10.0);
}

TEST(Resample, EdgeCases) {
  PoseTrack empty;
  EXPECT_TRUE(resample(empty, 30.0).empty());
  PoseTrack single;
  single.samples = {sample(3.0, 1.0, 2.0, 3.0)};
  ASSERT_EQ(resample(single, 60.0).size(), 1u);
  EXPECT_THROW(resample(single, 0.0), std::invalid_argument);
  EXPECT_THROW(resample(single, -30.0), std::invalid_argument);
  EXPECT_THROW(resample(single, std::nan("")), std::invalid_argument);
  PoseTrack year;
  year.samples = {sample(0.0, 0.0, 0.0, 0.0), sample(3.2e7, 0.0, 1.0, 0.0)};
  EXPECT_THROW(resample(year, 60.0), std::invalid_argument);  // ~1.9e9 frames
}

// --max-frames N of a long log at a high rate: only the N frames are computed (a year at
// 60 fps is 1.9e9 frames, refused whole; 4 hours at 1000 fps took 1.5 GB and 11 s before
// the first pose was sent).
TEST(Resample, MaxFramesComputesOnlyTheFramesKept) {
  PoseTrack year;
  const double t0 = 1.7e9;  // s since the Unix epoch
  year.samples = {sample(t0, 47.0, 8.0, 1000.0), sample(t0 + 3.2e7, 47.0, 9.0, 1000.0)};
  const auto frames = resample(year, 60.0, 3);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_DOUBLE_EQ(frames[0].unix_time_s, t0);
  EXPECT_NEAR(frames[2].unix_time_s, t0 + 2.0 / 60.0, 1e-6);
  EXPECT_THROW(resample(year, 60.0), std::invalid_argument);  // all of it: still refused

  // More frames asked for than the log has: the log's frames.
  PoseTrack short_track;
  short_track.samples = {sample(t0, 47.0, 8.0, 1000.0), sample(t0 + 1.0, 47.0, 8.001, 1000.0)};
  EXPECT_EQ(resample(short_track, 10.0, 1000).size(), 11u);

  // The replay path (sim_client replay / cigi --max-frames).
  const auto poses = replay_poses(year, 60.0, 3);
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_NEAR(poses[1].sim_time_s, 1.0 / 60.0, 1e-6);  // s; t0 + k / fps - t0 at Unix-time precision
}

}  // namespace
