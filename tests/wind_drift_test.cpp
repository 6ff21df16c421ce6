// Wind advection as a solid-body rotation of the cloud field (weather/wind_drift.h).
#include <gtest/gtest.h>

#include <cmath>

#include "weather/wind_drift.h"

namespace cloudsvc {
namespace {

TEST(WindDrift, CalmIsIdentity) {
  const glm::dmat3 r = wind_rotation({0.0, 0.0}, WindAnchor{{47.0, 8.0, 1500.0}, 1.0e9}, 1.0e9 + 86400.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(r[i][j], i == j ? 1.0 : 0.0);
}

// A cloud at the anchor point at t0 is found one minute later 60 s * wind downwind: the
// field sampled there (at rot * x) shows what was at the anchor.
TEST(WindDrift, AnchorMovesWithTheWind) {
  const WindAnchor anchor{{47.45, 8.56, 1500.0}, 1.7e9};
  const weather::Wind wind{8.0, 3.0};
  const glm::dvec3 p0 = geo::geodetic_to_ecef(anchor.position);
  const glm::dvec3 v_enu = geo::enu_to_ecef(47.45, 8.56) * glm::dvec3(8.0, 3.0, 0.0);
  // The field moves along the sphere: the wind's small component along the geocentric
  // radius (the ellipsoid normal is 0.19 deg off it here) is not a motion of the field.
  const glm::dvec3 r_hat = glm::normalize(p0);
  const glm::dvec3 v_sphere = v_enu - glm::dot(v_enu, r_hat) * r_hat;
  const glm::dvec3 v = v_sphere * (glm::length(v_enu) / glm::length(v_sphere));
  const double dt = 60.0;
  const glm::dmat3 r = wind_rotation(wind, anchor, anchor.unix_time_s + dt);
  const glm::dvec3 seen = r * (p0 + v * dt);
  EXPECT_LT(glm::length(seen - p0), 0.05) << "metres";  // sagitta over 512 m: 2 cm
}

TEST(WindDrift, RotationStaysOrthonormalAfterThirtyDays) {
  const WindAnchor anchor{{-33.9, 151.2, 2000.0}, 1.7e9};
  const glm::dmat3 r = wind_rotation({35.0, -12.0}, anchor, anchor.unix_time_s + 30.0 * 86400.0);
  const glm::dmat3 rtr = glm::transpose(r) * r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(rtr[i][j], i == j ? 1.0 : 0.0, 1e-12);
  EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
  // The anchor's radius is preserved (the field moves along the sphere).
  const glm::dvec3 p = geo::geodetic_to_ecef(anchor.position);
  EXPECT_NEAR(glm::length(r * p), glm::length(p), 1e-6);
}

// The motion is one rotation of the globe: two points far apart move at the speed the
// rotation gives them, independent of any camera.
TEST(WindDrift, SpeedFallsOffAwayFromTheAnchorGreatCircle) {
  const WindAnchor anchor{{0.0, 0.0, 0.0}, 0.0};
  const glm::dmat3 r = wind_rotation({10.0, 0.0}, anchor, 1000.0);  // eastward at the equator
  const glm::dvec3 pole = geo::geodetic_to_ecef({90.0, 0.0, 0.0});
  EXPECT_LT(glm::length(r * pole - pole), 1e-6) << "rotation axis is the polar axis";
  const glm::dvec3 eq = geo::geodetic_to_ecef({0.0, 90.0, 0.0});
  EXPECT_NEAR(glm::length(r * eq - eq), 10.0 * 1000.0, 1.0);
}

}  // namespace
}  // namespace cloudsvc
