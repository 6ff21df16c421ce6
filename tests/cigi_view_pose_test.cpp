// A CIGI view's eye and attitude from the ownship's pose and the view's offset and rotation
// (protocol/cigi/cigi_view_pose.h).
#include <gtest/gtest.h>

#include <random>

#include "protocol/cigi/cigi_view_pose.h"

namespace cloudsvc::cigi {
namespace {

double angle_diff(double a, double b) { return std::remainder(a - b, 360.0); }

TEST(CigiViewPose, AttitudesSurviveAxesAndBack) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> heading(0.0, 360.0), pitch(-89.0, 89.0), roll(-180.0, 180.0);
  for (int i = 0; i < 1000; ++i) {
    const geo::Attitude a{heading(rng), pitch(rng), roll(rng)};
    const geo::Attitude b = geo::attitude_of(geo::body_axes_enu(a));
    ASSERT_NEAR(angle_diff(b.heading_deg, a.heading_deg), 0.0, 1e-9);
    ASSERT_NEAR(b.pitch_deg, a.pitch_deg, 1e-9);
    ASSERT_NEAR(angle_diff(b.roll_deg, a.roll_deg), 0.0, 1e-9);
  }
  const geo::Attitude up = geo::attitude_of(geo::body_axes_enu({30.0, 90.0, 0.0}));
  EXPECT_NEAR(up.pitch_deg, 90.0, 1e-9);
  EXPECT_NEAR(up.heading_deg, 30.0, 1e-6);
}

TEST(CigiViewPose, ViewsTurnAndMoveWithTheOwnship) {
  const OwnshipPose own{47.0, 8.0, 3000.0, 0.0, 10.0, 90.0};  // heading east, nose 10° up
  View v;
  EXPECT_NEAR(view_pose(own, v).attitude.heading_deg, 90.0, 1e-9);
  EXPECT_NEAR(view_pose(own, v).attitude.pitch_deg, 10.0, 1e-9);
  EXPECT_NEAR(view_pose(own, v).position.alt_m, 3000.0, 1e-6);
  // A view turned 60° right of the nose looks 60° right of it; one pitched 10° down with a
  // level ownship's wings looks level.
  v.yaw_deg = 60.0;
  const geo::Attitude right = view_pose({47.0, 8.0, 3000.0, 0.0, 0.0, 90.0}, v).attitude;
  EXPECT_NEAR(right.heading_deg, 150.0, 1e-6);
  EXPECT_NEAR(right.pitch_deg, 0.0, 1e-6);
  v.yaw_deg = 0.0;
  v.pitch_deg = -10.0;
  EXPECT_NEAR(view_pose(own, v).attitude.pitch_deg, 0.0, 1e-6);
  // The eye 10 m ahead of an eastbound ownship is 10 m east; 2 m "down" in z is 2 m lower.
  View eye;
  eye.x_m = 10.0f;
  eye.z_m = 2.0f;
  const ViewPose p = view_pose({47.0, 8.0, 3000.0, 0.0, 0.0, 90.0}, eye);
  const glm::dvec3 moved = geo::geodetic_to_ecef(p.position) - geo::geodetic_to_ecef({47.0, 8.0, 3000.0});
  const glm::dmat3 enu = glm::transpose(geo::enu_to_ecef(47.0, 8.0));
  const glm::dvec3 local = enu * moved;
  EXPECT_NEAR(local.x, 10.0, 1e-6);
  EXPECT_NEAR(local.y, 0.0, 1e-6);
  EXPECT_NEAR(local.z, -2.0, 1e-6);
  // With the ownship banked 90° right, "right" (y) points down.
  View wing;
  wing.y_m = 5.0f;
  const ViewPose banked = view_pose({47.0, 8.0, 3000.0, 90.0, 0.0, 0.0}, wing);
  EXPECT_NEAR(banked.position.alt_m, 2995.0, 1e-6);
}

}  // namespace
}  // namespace cloudsvc::cigi
