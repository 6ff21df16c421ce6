// WGS84 frames: geodetic <-> ECEF, local ENU frames, aircraft body axes, radii of
// curvature, longitude wrapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/glm.hpp>

#include "geodesy/geodetic.h"

namespace {

using namespace cloudsvc::geo;

constexpr double kA = 6378137.0;              // WGS84 semi-major axis, m
constexpr double kF = 1.0 / 298.257223563;    // WGS84 flattening
constexpr double kB = kA * (1.0 - kF);        // semi-minor axis, m
constexpr double kDegToRad = std::numbers::pi / 180.0;

void expect_vec_near(const glm::dvec3& a, const glm::dvec3& b, double tol, const char* what) {
  EXPECT_LE(glm::length(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z
                                     << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")";
}

// --- geodetic <-> ECEF ----------------------------------------------------------------

// GeographicLib's documented check value (GeographicLib Geocentric documentation /
// CartConvert example; docs/SOURCES.md, "Geodesy and sun").
TEST(Geodetic, GeographicLibCheckValue) {
  const glm::dvec3 p = geodetic_to_ecef({47.4, 8.5, 10000.0});
  EXPECT_NEAR(p.x, 4284246.2561, 1e-3);
  EXPECT_NEAR(p.y, 640284.8930, 1e-3);
  EXPECT_NEAR(p.z, 4679340.3816, 1e-3);
}

// Closed forms on the axes: equator (a + h, 0, 0), poles (0, 0, +/-(b + h)).
TEST(Geodetic, AxesClosedForm) {
  expect_vec_near(geodetic_to_ecef({0, 0, 0}), {kA, 0, 0}, 1e-9, "equator lon 0");
  expect_vec_near(geodetic_to_ecef({0, 90, 100}), {0, kA + 100, 0}, 1e-9, "equator lon 90");
  expect_vec_near(geodetic_to_ecef({0, 180, 0}), {-kA, 0, 0}, 1e-9, "equator lon 180");
  expect_vec_near(geodetic_to_ecef({90, 0, 0}), {0, 0, kB}, 1e-9, "north pole");
  expect_vec_near(geodetic_to_ecef({-90, 33, 1000}), {0, 0, -(kB + 1000)}, 1e-9, "south pole");
}

TEST(Geodetic, RoundTripEdgeCases) {
  const double lats[] = {-90.0, -89.9999999, -60.0, -1e-12, 0.0, 45.0, 89.9999999, 90.0};
  const double lons[] = {-180.0, -179.9999, -90.0, 0.0, 1e-12, 179.9999, 180.0};
  const double alts[] = {-500.0, 0.0, 10000.0, 100000.0};
  for (double lat : lats) {
    for (double lon : lons) {
      for (double alt : alts) {
        SCOPED_TRACE(testing::Message() << "lat " << lat << " lon " << lon << " alt " << alt);
        const glm::dvec3 p = geodetic_to_ecef({lat, lon, alt});
        const Geodetic g = ecef_to_geodetic(p);
        EXPECT_NEAR(g.alt_m, alt, 1e-6);
        EXPECT_NEAR(g.lat_deg, lat, 1e-9);
        if (std::fabs(lat) == 90.0) {
          // Longitude is arbitrary at the poles: compare the positions instead.
          expect_vec_near(geodetic_to_ecef(g), p, 1e-6, "pole ECEF");
        } else {
          // +180 and -180 are the same meridian: compare the wrapped difference.
          EXPECT_NEAR(std::remainder(g.lon_deg - lon, 360.0), 0.0, 1e-9);
          EXPECT_GE(g.lon_deg, -180.0);
          EXPECT_LE(g.lon_deg, 180.0);
        }
        // ECEF -> geodetic -> ECEF closes to well below a micrometre everywhere.
        expect_vec_near(geodetic_to_ecef(g), p, 1e-6, "ECEF round trip");
      }
    }
  }
}

// A dense sweep: worst round-trip error over the globe and 0..100 km.
TEST(Geodetic, RoundTripSweep) {
  double worst_m = 0.0, worst_deg = 0.0;
  for (int i = 0; i <= 180; ++i) {
    const double lat = -90.0 + i * 1.0;
    for (int j = 0; j < 72; ++j) {
      const double lon = -180.0 + j * 5.0 + 0.123;
      for (double alt : {-500.0, 0.0, 2000.0, 10000.0, 100000.0}) {
        const glm::dvec3 p = geodetic_to_ecef({lat, lon, alt});
        const Geodetic g = ecef_to_geodetic(p);
        worst_m = std::max(worst_m, std::fabs(g.alt_m - alt));
        worst_m = std::max(worst_m, glm::length(geodetic_to_ecef(g) - p));
        worst_deg = std::max(worst_deg, std::fabs(g.lat_deg - lat));
        if (std::fabs(lat) < 90.0)
          worst_deg = std::max(worst_deg, std::fabs(std::remainder(g.lon_deg - lon, 360.0)));
      }
    }
  }
  std::printf("round trip worst: %.3g m, %.3g deg\n", worst_m, worst_deg);
  EXPECT_LT(worst_m, 1e-6);
  EXPECT_LT(worst_deg, 1e-9);
}

// --- ENU frame -----------------------------------------------------------------------

TEST(EnuFrame, OrthonormalRightHandedAndUpIsNormal) {
  for (double lat : {-90.0, -67.5, -30.0, 0.0, 12.3, 47.4, 80.0, 90.0}) {
    for (double lon : {-180.0, -100.0, 0.0, 8.5, 179.9999, 180.0}) {
      SCOPED_TRACE(testing::Message() << "lat " << lat << " lon " << lon);
      const glm::dmat3 m = enu_to_ecef(lat, lon);
      const glm::dvec3 e = m[0], n = m[1], u = m[2];
      EXPECT_NEAR(glm::dot(e, e), 1.0, 1e-15);
      EXPECT_NEAR(glm::dot(n, n), 1.0, 1e-15);
      EXPECT_NEAR(glm::dot(u, u), 1.0, 1e-15);
      EXPECT_NEAR(glm::dot(e, n), 0.0, 1e-15);
      EXPECT_NEAR(glm::dot(e, u), 0.0, 1e-15);
      EXPECT_NEAR(glm::dot(n, u), 0.0, 1e-15);
      expect_vec_near(glm::cross(e, n), u, 1e-15, "east x north = up");
      // Up is the ellipsoid normal: gradient of x^2/a^2 + y^2/a^2 + z^2/b^2 at the
      // surface point below.
      const glm::dvec3 p = geodetic_to_ecef({lat, lon, 0.0});
      const glm::dvec3 grad = glm::normalize(glm::dvec3(p.x / (kA * kA), p.y / (kA * kA),
                                                        p.z / (kB * kB)));
      expect_vec_near(u, grad, 1e-12, "up vs ellipsoid normal");
      // Up is also the direction of increasing altitude at fixed lat/lon.
      const glm::dvec3 dh = geodetic_to_ecef({lat, lon, 1000.0}) - p;
      expect_vec_near(u, dh / 1000.0, 1e-9, "up vs d(ECEF)/dh");
    }
  }
}

TEST(EnuFrame, EastAndNorthFollowCoordinateLines) {
  // Away from the poles: north = d(ECEF)/d(lat) and east = d(ECEF)/d(lon), normalised
  // (central differences; GeographicLib does the evaluation).
  for (double lat : {-75.0, -20.0, 0.0, 47.4, 70.0}) {
    for (double lon : {-179.0, -45.0, 0.0, 8.5, 120.0}) {
      SCOPED_TRACE(testing::Message() << "lat " << lat << " lon " << lon);
      const double d = 1e-5;
      const glm::dmat3 m = enu_to_ecef(lat, lon);
      const glm::dvec3 dn =
          geodetic_to_ecef({lat + d, lon, 500.0}) - geodetic_to_ecef({lat - d, lon, 500.0});
      const glm::dvec3 de =
          geodetic_to_ecef({lat, lon + d, 500.0}) - geodetic_to_ecef({lat, lon - d, 500.0});
      expect_vec_near(m[1], glm::normalize(dn), 1e-8, "north");
      expect_vec_near(m[0], glm::normalize(de), 1e-8, "east");
    }
  }
  // At the north pole with lon 0, north points towards -X (towards lon 180), east +Y.
  const glm::dmat3 pole = enu_to_ecef(90.0, 0.0);
  expect_vec_near(pole[1], {-1, 0, 0}, 1e-15, "north at pole");
  expect_vec_near(pole[0], {0, 1, 0}, 1e-15, "east at pole");
}

// --- Body axes ------------------------------------------------------------------------

// Rotation of v about a unit axis by angle (radians), right-hand rule (Rodrigues).
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

// Independent construction of the 3-2-1 sequence: intrinsic yaw, pitch, roll equals the
// extrinsic sequence roll about North, pitch about East, yaw about Up applied to the
// level, north-facing axes (forward N, right E, up U). Signs: right wing down rotates
// E towards -U (+roll about N); nose up rotates N towards U (+pitch about E); heading is
// clockwise seen from above (-heading about U).
BodyAxes reference_axes(const Attitude& a) {
  const glm::dvec3 E(1, 0, 0), N(0, 1, 0), U(0, 0, 1);
  auto apply = [&](glm::dvec3 v) {
    v = rotate(v, N, a.roll_deg * kDegToRad);
    v = rotate(v, E, a.pitch_deg * kDegToRad);
    v = rotate(v, U, -a.heading_deg * kDegToRad);
    return v;
  };
  return {apply(N), apply(E), apply(U)};
}

TEST(BodyAxes, KnownAttitudes) {
  const double t = 1e-15;
  BodyAxes b = body_axes_enu({0, 0, 0});
  expect_vec_near(b.forward, {0, 1, 0}, t, "level north: forward");
  expect_vec_near(b.right, {1, 0, 0}, t, "level north: right");
  expect_vec_near(b.up, {0, 0, 1}, t, "level north: up");

  b = body_axes_enu({90, 0, 0});
  expect_vec_near(b.forward, {1, 0, 0}, t, "heading 90: forward east");
  expect_vec_near(b.right, {0, -1, 0}, t, "heading 90: right south");
  expect_vec_near(b.up, {0, 0, 1}, t, "heading 90: up");

  b = body_axes_enu({180, 0, 0});
  expect_vec_near(b.forward, {0, -1, 0}, t, "heading 180: forward south");
  b = body_axes_enu({270, 0, 0});
  expect_vec_near(b.forward, {-1, 0, 0}, t, "heading 270: forward west");

  b = body_axes_enu({0, 90, 0});
  expect_vec_near(b.forward, {0, 0, 1}, t, "pitch 90: forward up");
  expect_vec_near(b.right, {1, 0, 0}, t, "pitch 90: right east");
  expect_vec_near(b.up, {0, -1, 0}, t, "pitch 90: canopy backwards (south)");

  b = body_axes_enu({0, -30, 0});
  expect_vec_near(b.forward, {0, std::sqrt(3.0) / 2.0, -0.5}, 1e-15, "pitch -30: nose down");

  b = body_axes_enu({0, 0, 90});
  expect_vec_near(b.forward, {0, 1, 0}, t, "roll 90: forward");
  expect_vec_near(b.right, {0, 0, -1}, t, "roll 90: right wing down");
  expect_vec_near(b.up, {1, 0, 0}, t, "roll 90: canopy to the right (east)");

  // Order matters: heading 90 then roll 90 -> right wing still points down, canopy south.
  b = body_axes_enu({90, 0, 90});
  expect_vec_near(b.forward, {1, 0, 0}, t, "hdg 90 roll 90: forward");
  expect_vec_near(b.right, {0, 0, -1}, t, "hdg 90 roll 90: right down");
  expect_vec_near(b.up, {0, -1, 0}, t, "hdg 90 roll 90: canopy south");

  // Pitch 45 then roll 90: nose stays at 45 deg up (roll is about the nose axis).
  b = body_axes_enu({0, 45, 90});
  expect_vec_near(b.forward, {0, std::sqrt(0.5), std::sqrt(0.5)}, 1e-15, "pitch 45 roll 90");
  EXPECT_NEAR(b.right.z, -std::sqrt(0.5), 1e-15);
}

TEST(BodyAxes, MatchesIndependentConstructionAndIsRightHanded) {
  unsigned state = 7u;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1u << 24);
  };
  for (int i = 0; i < 2000; ++i) {
    const Attitude a{360.0 * uniform() - 180.0, 180.0 * uniform() - 90.0,
                     360.0 * uniform() - 180.0};
    const BodyAxes b = body_axes_enu(a);
    const BodyAxes r = reference_axes(a);
    expect_vec_near(b.forward, r.forward, 1e-14, "forward");
    expect_vec_near(b.right, r.right, 1e-14, "right");
    expect_vec_near(b.up, r.up, 1e-14, "up");
    EXPECT_NEAR(glm::length(b.forward), 1.0, 1e-15);
    EXPECT_NEAR(glm::dot(b.forward, b.right), 0.0, 1e-15);
    expect_vec_near(glm::cross(b.right, b.forward), b.up, 1e-15, "up = right x forward");
    // Forward depends on heading and pitch only; its elevation angle is the pitch.
    EXPECT_NEAR(std::asin(b.forward.z) / kDegToRad, a.pitch_deg, 1e-9);
  }
}

// --- Radii of curvature -----------------------------------------------------------------

TEST(Radii, ClosedFormsAtEquator45AndPole) {
  // Equator: M = b^2 / a, N = a, sqrt(MN) = b.
  EXPECT_NEAR(meridional_radius(0.0), kB * kB / kA, 1e-6);
  EXPECT_NEAR(prime_vertical_radius(0.0), kA, 1e-6);
  EXPECT_NEAR(gaussian_radius(0.0), kB, 1e-6);
  // Poles: M = N = a^2 / b.
  for (double lat : {90.0, -90.0}) {
    EXPECT_NEAR(meridional_radius(lat), kA * kA / kB, 1e-6);
    EXPECT_NEAR(prime_vertical_radius(lat), kA * kA / kB, 1e-6);
    EXPECT_NEAR(gaussian_radius(lat), kA * kA / kB, 1e-6);
  }
  // 45 deg: sin^2 = 1/2, so 1 - e^2/2 = (a^2 + b^2) / (2 a^2) and
  // sqrt(MN) = a (b/a) / (1 - e^2/2) = 2 a^2 b / (a^2 + b^2).
  EXPECT_NEAR(gaussian_radius(45.0), 2.0 * kA * kA * kB / (kA * kA + kB * kB), 1e-6);
  EXPECT_NEAR(gaussian_radius(-45.0), gaussian_radius(45.0), 1e-9);
  // Numbers for orientation: 6356752.3142 m, 6399593.6258 m.
  EXPECT_NEAR(gaussian_radius(0.0), 6356752.3142, 1e-3);
  EXPECT_NEAR(gaussian_radius(90.0), 6399593.6258, 1e-3);
}

TEST(Radii, MatchArcLengthsOfTheEllipsoid) {
  // M = |d(ECEF)/d(lat)|, N cos(lat) = |d(ECEF)/d(lon)| (per radian, at h = 0), both by
  // central differences of GeographicLib positions.
  for (double lat : {-80.0, -45.0, -10.0, 0.0, 30.0, 60.0, 85.0}) {
    const double d = 1e-4;  // deg
    const double m_num = glm::length(geodetic_to_ecef({lat + d, 10.0, 0.0}) -
                                      geodetic_to_ecef({lat - d, 10.0, 0.0})) /
                          (2.0 * d * kDegToRad);
    const double n_num = glm::length(geodetic_to_ecef({lat, 10.0 + d, 0.0}) -
                                      geodetic_to_ecef({lat, 10.0 - d, 0.0})) /
                         (2.0 * d * kDegToRad * std::cos(lat * kDegToRad));
    EXPECT_NEAR(meridional_radius(lat), m_num, 1e-3) << lat;
    EXPECT_NEAR(prime_vertical_radius(lat), n_num, 1e-3) << lat;
    EXPECT_LE(meridional_radius(lat), prime_vertical_radius(lat));
    EXPECT_NEAR(gaussian_radius(lat),
                std::sqrt(meridional_radius(lat) * prime_vertical_radius(lat)), 1e-8);
  }
}

// --- Longitude wrapping ----------------------------------------------------------------

TEST(WrapLongitude, IntoHalfOpenRange) {
  EXPECT_EQ(wrap_longitude_deg(0.0), 0.0);
  EXPECT_EQ(wrap_longitude_deg(180.0), -180.0);
  EXPECT_EQ(wrap_longitude_deg(-180.0), -180.0);
  EXPECT_EQ(wrap_longitude_deg(540.0), -180.0);
  EXPECT_EQ(wrap_longitude_deg(-540.0), -180.0);
  EXPECT_EQ(wrap_longitude_deg(190.0), -170.0);
  EXPECT_EQ(wrap_longitude_deg(-190.0), 170.0);
  EXPECT_EQ(wrap_longitude_deg(360.0), 0.0);
  EXPECT_EQ(wrap_longitude_deg(719.5), -0.5);
  EXPECT_EQ(wrap_longitude_deg(179.9999), 179.9999);
  EXPECT_EQ(wrap_longitude_deg(-179.9999), -179.9999);
  // Exact: tiny longitudes survive (fmod(lon + 180, 360) - 180 would round them to 0).
  EXPECT_EQ(wrap_longitude_deg(1e-20), 1e-20);
  EXPECT_EQ(wrap_longitude_deg(-1e-20), -1e-20);
  EXPECT_EQ(wrap_longitude_deg(360.0 * 1000.0 + 12.5), 12.5);
  for (double x = -1000.0; x <= 1000.0; x += 0.37) {
    const double w = wrap_longitude_deg(x);
    ASSERT_GE(w, -180.0);
    ASSERT_LT(w, 180.0);
    ASSERT_NEAR(std::remainder(w - x, 360.0), 0.0, 1e-12);
  }
}

}  // namespace
