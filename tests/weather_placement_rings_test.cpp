// Geometry of the placement rings (weather/placement_rings.h) and the covered fraction they
// keep of the levels too small to draw (CloudPlacement::covered_below).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "weather/cloud_placement.h"
#include "weather/placement_rings.h"

namespace cloudsvc::weather {
namespace {

TEST(PlacementRings, PlaneCoordinatesAndShellPointsAreInverse) {
  const double R = 6371000.0 + 2000.0;
  for (const glm::dvec3& dir : {glm::dvec3(0.3, -0.5, 0.8), glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(0.0, 0.0, -1.0),
                                glm::dvec3(-1.0, 1e-9, 0.0)}) {
    const glm::dvec3 C = R * glm::normalize(dir);
    const RingPlane plane = ring_plane(C);
    EXPECT_NEAR(glm::dot(plane.e, plane.c), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(plane.n, plane.c), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(plane.e), 1.0, 1e-12);
    for (const glm::dvec2 uv : {glm::dvec2(0.0), glm::dvec2(16.0, -3.0), glm::dvec2(-2.0e5, 1.5e5)}) {
      const glm::dvec3 d = ring_point_from_centre(plane, R, uv);
      EXPECT_NEAR(glm::length(C + d), R, 1e-6) << "on the shell";
      const glm::dvec2 back = ring_plane_coords(plane, R, C + d);
      EXPECT_NEAR(back.x, uv.x, 1e-6);
      EXPECT_NEAR(back.y, uv.y, 1e-6);
    }
    // near the centre the plane's metres are the shell's
    const glm::dvec3 d = ring_point_from_centre(plane, R, glm::dvec2(100.0, 0.0));
    EXPECT_NEAR(glm::length(d), 100.0, 1e-6);
  }
}

TEST(PlacementRings, EachRingDrawsTheLevelsItResolves) {
  RingLayout layout;  // 32 m texels, 3 texels a radius
  PlacementParams p;  // cells 500 m .. 16 km, rho from 0.2
  EXPECT_EQ(ring_texel_m(layout, 0), 32.0);
  EXPECT_EQ(ring_texel_m(layout, 5), 1024.0);
  for (int ring = 0; ring < 7; ++ring) {
    const int first = ring_first_level(layout, p, ring);
    if (first < p.levels) {
      EXPECT_GE(p.rho_min * p.smallest_cell_m * std::ldexp(1.0, first), 3.0 * ring_texel_m(layout, ring));
    }
    if (first > 0) {
      EXPECT_LT(p.rho_min * p.smallest_cell_m * std::ldexp(1.0, first - 1), 3.0 * ring_texel_m(layout, ring));
    }
  }
  EXPECT_EQ(ring_first_level(layout, p, 0), 0);
  EXPECT_EQ(ring_first_level(layout, p, 6), p.levels) << "nothing left to draw";
}

TEST(PlacementRings, TheCoveredFractionOfAllLevelsIsTheCoverage) {
  const CloudPlacement cp({}, 6373000.0, 3);
  for (double c : {0.0, 0.1, 0.35, 0.6}) {
    ASSERT_LT(c, cp.max_coverage());
    EXPECT_NEAR(cp.covered_below(cp.params().levels, c), c, 2e-3) << c;
    EXPECT_EQ(cp.covered_below(0, c), 0.0);
    EXPECT_LE(cp.covered_below(2, c), cp.covered_below(3, c));
  }
}

}  // namespace
}  // namespace cloudsvc::weather
