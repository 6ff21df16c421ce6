// weather/cumulus_domes: the dome model's seeds, warp and continuity (the morphology against
// observations is measured in reference_cumulus_domes_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "weather/cumulus_domes.h"
#include "weather/dome_rings.h"

namespace cloudsvc::weather {
namespace {

constexpr double kR = kDomeShellRadius_m;

glm::dvec3 shell_point(double lat_deg, double lon_deg) {
  const double la = lat_deg * M_PI / 180.0, lo = lon_deg * M_PI / 180.0;
  return kR * glm::dvec3(std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la));
}

Weather three_layers() {
  Weather w;
  w.map_seed = 9;
  w.layers = {default_layer(CloudType::Cumulus), default_layer(CloudType::Altocumulus), default_layer(CloudType::Cumulus)};
  return w;
}

TEST(CumulusDomes, OnlyCumulusIsDrawnAsDomes) {
  for (CloudType t : all_cloud_types()) EXPECT_EQ(uses_domes(t), t == CloudType::Cumulus) << cloud_type_name(t);
}

// A layer's clouds stay where they are when another layer comes or goes.
TEST(CumulusDomes, SeedDependsOnTheMapTheTypeAndTheOrdinalOnly) {
  const Weather w = three_layers();
  Weather without_alto = w;
  without_alto.layers.erase(without_alto.layers.begin() + 1);
  EXPECT_EQ(dome_placement_seed(w, 2), dome_placement_seed(without_alto, 1));
  Weather without_first = w;
  without_first.layers.erase(without_first.layers.begin());
  EXPECT_EQ(dome_placement_seed(w, 1), dome_placement_seed(without_first, 0)) << "the altocumulus layer";
  EXPECT_NE(dome_placement_seed(w, 0), dome_placement_seed(w, 2)) << "two cumulus layers differ";
  Weather other_map = w;
  other_map.map_seed = 10;
  EXPECT_NE(dome_placement_seed(w, 0), dome_placement_seed(other_map, 0));
}

TEST(CumulusDomes, BrokenFieldsHoldRelativelyMoreLargeClouds) {
  EXPECT_GT(dome_placement_params(0.35).size_exponent, dome_placement_params(0.65).size_exponent);
  EXPECT_DOUBLE_EQ(dome_largest_radius_m(), 2000.0);
}

TEST(CumulusDomes, WarpStaysOnTheShellWithinItsBound) {
  const DomeWarp warp(3);
  double largest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 x = shell_point(-89.0 + 0.089 * i, -179.0 + 0.179 * i * 7 - 360.0 * std::floor((0.179 * i * 7) / 360.0));
    const glm::dvec3 y = warp.warped(x);
    EXPECT_NEAR(glm::length(y), kR, 1e-6);
    largest = std::max(largest, glm::length(y - x));
  }
  std::printf("largest displacement %.0f m (bound %.0f m)\n", largest, DomeWarp::max_displacement_m());
  EXPECT_LT(largest, DomeWarp::max_displacement_m());
  EXPECT_GT(largest, 0.2 * DomeWarp::max_displacement_m()) << "the warp displaces by hundreds of metres";
  // level of detail: octaves of wavelength >= 4 texels
  EXPECT_EQ(dome_warp_octaves(32.0), kDomeWarpOctaves);
  EXPECT_EQ(dome_warp_octaves(256.0), 4);  // 8, 4, 2, 1 km: wavelengths of >= 3.5 texels
  EXPECT_EQ(dome_warp_octaves(300.0), 3);
  EXPECT_EQ(dome_warp_octaves(4000.0), 0);
}

// No seam at the antimeridian or the poles: 1 m steps across them change the top no more
// than 1 m steps elsewhere do.
TEST(CumulusDomes, TopIsContinuousAcrossTheAntimeridianAndThePoles) {
  const CloudPlacement cp(dome_placement_params(0.6), kR, 21);
  const DomeWarp warp(21);
  const auto cov = [](const glm::dvec3&) { return 0.6; };
  const auto top = [&](const glm::dvec3& x) { return dome_top_unit_aspect(cp, warp, x, cov, 0, kDomeLevels, 5000.0); };
  double step_elsewhere = 0.0, step_seam = 0.0;
  for (double lat = -80.0; lat <= 80.0; lat += 0.53) {
    const double la = lat * M_PI / 180.0, dlon = 0.5 / (kR * std::cos(la)) * 180.0 / M_PI;
    step_seam = std::max(step_seam, std::abs(top(shell_point(lat, 180.0 - dlon)) - top(shell_point(lat, -180.0 + dlon))));
    step_elsewhere = std::max(step_elsewhere, std::abs(top(shell_point(lat, 37.0 - dlon)) - top(shell_point(lat, 37.0 + dlon))));
  }
  for (double lon = -180.0; lon < 180.0; lon += 1.1) {
    const double d = 0.5 / kR * 180.0 / M_PI;  // 0.5 m from the pole each side
    step_seam = std::max(step_seam, std::abs(top(shell_point(90.0 - d, lon)) - top(shell_point(90.0 - d, lon + 180.0))));
    step_seam = std::max(step_seam, std::abs(top(shell_point(-90.0 + d, lon)) - top(shell_point(-90.0 + d, lon + 180.0))));
  }
  std::printf("largest change over 1 m: across the seams %.3f m, elsewhere %.3f m\n", step_seam, step_elsewhere);
  EXPECT_LT(step_seam, std::max(3.0 * step_elsewhere, 1.0));
}

// The rings follow the camera in steps (a pure function of its position, which the CPU
// reference recomputes): every ring keeps the nadir within 1/16 of its width of its centre,
// their texels stay on one grid of the anchor's plane, and a camera moving 100 m mostly
// keeps its rings.
TEST(DomeRings, FollowTheCameraInStepsOnOneTexelGrid) {
  const RingLayout layout = dome_ring_layout();
  int unchanged = 0, moves = 0;
  for (double lat = -89.9; lat < 90.0; lat += 7.3)
    for (double lon = -179.95; lon < 180.0; lon += 23.9) {
      const glm::dvec3 camera = (kR + 4000.0) / kR * shell_point(lat, lon);
      const DomeRings r = dome_rings_for(layout, camera);
      EXPECT_NEAR(glm::length(r.anchor), kR, 1e-6);
      EXPECT_LT(glm::distance(r.anchor, kR * glm::normalize(camera)), kDomeAnchorCell_m) << lat << " " << lon;
      const glm::dvec2 nadir = ring_plane_coords(r.plane, kR, camera);
      for (int k = 0; k < layout.rings; ++k) {
        const double h = ring_texel_m(layout, k);
        const glm::dvec2 off = glm::abs(nadir - r.origin[k]) / h;
        EXPECT_LE(std::max(off.x, off.y), layout.size / 16.0 + 1e-9) << k;
        // the origin is a whole number of texels from the plane's origin: one texel grid
        const glm::dvec2 t = r.origin[k] / h;
        EXPECT_NEAR(t.x, std::round(t.x), 1e-9);
        EXPECT_NEAR(t.y, std::round(t.y), 1e-9);
        EXPECT_DOUBLE_EQ(dome_ring_weight(layout, r, k, nadir), 1.0);
      }
      const DomeRings moved = dome_rings_for(layout, camera + 100.0 * r.plane.e);
      ++moves;
      unchanged += moved == r;
    }
  std::printf("%d of %d 100 m moves keep every ring\n", unchanged, moves);
  EXPECT_GT(unchanged, moves * 8 / 10);
}

}  // namespace
}  // namespace cloudsvc::weather
