// The ground's albedo where tiles set it (weather/ground_albedo_map.h): the global albedo
// elsewhere, the tiles' where they reach, blended over one texel at their edges, across the
// antimeridian and without a seam at the poles; and the tile channel's place among a
// tile's values.
#include <gtest/gtest.h>

#include <cmath>

#include "weather/ground_albedo_map.h"
#include "weather_tile_support.h"

namespace cloudsvc::weather {
namespace {

const glm::dvec3 kGlobal{0.14, 0.12, 0.08};  // the renderer's land default

MapTile albedo_tile(double lat0, double lon0, double lat1, double lon1, float albedo) {
  MapTile t = test::coverage_tile(lat0, lon0, lat1, lon1, albedo);
  t.channels = kGroundAlbedoTileChannel;
  return t;
}

TEST(GroundAlbedoMap, EmptyMapIsTheGlobalAlbedo) {
  const GroundAlbedoMap m(360, 180);
  EXPECT_FALSE(m.any());
  const glm::dvec3 a = m.at(45.0, 10.0, kGlobal);
  EXPECT_EQ(a, kGlobal);
}

TEST(GroundAlbedoMap, TilesSetTheirAreaOnly) {
  GroundAlbedoMap m(360, 180);
  const std::uint64_t v0 = m.version();
  m.apply(albedo_tile(40, 0, 50, 20, 0.8f));
  EXPECT_TRUE(m.any());
  EXPECT_GT(m.version(), v0);
  const glm::dvec3 in = m.at(45.0, 10.0, kGlobal);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(in[c], 0.8, 1e-6) << "grey inside the tile";
  const glm::dvec3 out = m.at(30.0, 10.0, kGlobal);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[c], kGlobal[c], 1e-6) << "global outside";
  // Half a texel outside the tile's edge (texel centres at 49.5 and 50.5): half of each.
  const glm::dvec3 edge = m.at(50.0, 10.0, kGlobal);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(edge[c], 0.5 * (0.8 + kGlobal[c]), 1e-6);
  // A later tile overrides; a sea tile inside the snow one.
  m.apply(albedo_tile(44, 8, 46, 12, 0.06f));
  EXPECT_NEAR(m.at(45.0, 10.0, kGlobal).g, 0.06, 1e-6);
  EXPECT_NEAR(m.at(42.0, 10.0, kGlobal).g, 0.8, 1e-6);
  m.clear();
  EXPECT_FALSE(m.any());
  EXPECT_EQ(m.at(45.0, 10.0, kGlobal), kGlobal);
}

TEST(GroundAlbedoMap, AcrossTheAntimeridianAndAtThePoles) {
  GroundAlbedoMap m(360, 180);
  m.apply(albedo_tile(-10, 170, 10, 200, 0.3f));  // 170E .. 160W
  EXPECT_NEAR(m.at(0.0, 175.0, kGlobal).g, 0.3, 1e-6);
  EXPECT_NEAR(m.at(0.0, -175.0, kGlobal).g, 0.3, 1e-6);
  EXPECT_NEAR(m.at(0.0, -150.0, kGlobal).g, kGlobal.g, 1e-6);
  // Snow over half the Antarctic cap: at the pole every longitude gives the same value.
  m.apply(albedo_tile(-90, 0, -80, 180, 0.8f));
  const double at_pole = m.at(-90.0, 0.0, kGlobal).g;
  for (double lon : {-170.0, -90.0, 45.0, 135.0}) EXPECT_NEAR(m.at(-90.0, lon, kGlobal).g, at_pole, 1e-6) << lon;
  EXPECT_NEAR(at_pole, 0.5 * (0.8 + kGlobal.g), 0.01);  // half the ring is snow
  EXPECT_NEAR(m.at(-85.0, 90.0, kGlobal).g, 0.8, 1e-6);
  EXPECT_NEAR(m.at(-85.0, -90.0, kGlobal).g, kGlobal.g, 1e-6);
}

// In a tile with weather channels too, the albedo is each texel's last value (ascending
// bit order), and the weather map takes the others (apply_tile).
TEST(GroundAlbedoMap, TakesTheLastValueOfEachTexel) {
  MapTile t = test::coverage_tile(40, 0, 50, 20, 0.0f);
  t.channels = 0x01 | kGroundAlbedoTileChannel;  // coverage, albedo
  t.data.resize(t.data.size() * 2);
  for (std::size_t i = 0; i < t.data.size(); i += 2) {
    t.data[i] = 0.9f;       // coverage
    t.data[i + 1] = 0.7f;   // albedo
  }
  ASSERT_TRUE(t.problem().empty()) << t.problem();
  GroundAlbedoMap m(360, 180);
  m.apply(t);
  EXPECT_NEAR(m.at(45.0, 10.0, kGlobal).g, 0.7, 1e-6);
  WeatherMap w;
  w.width = 360;
  w.height = 180;
  w.rgba.assign(360u * 180u * 4u, 0.5f);
  apply_tile(w, t);
  float v[4];
  w.sample(45.0, 10.0, v);
  EXPECT_NEAR(v[0], 0.9f, 1e-6);
  EXPECT_NEAR(v[1], 0.5f, 1e-6) << "the albedo goes to no weather channel";
  EXPECT_NEAR(v[3], 0.5f, 1e-6);
  // A value out of range is named by its channel.
  t.data[1] = 1.5f;
  EXPECT_EQ(t.problem(), "MapTile.data[1] 1.5 out of range [0, 1] (col 0, row 0, ground_albedo)");
}

}  // namespace
}  // namespace cloudsvc::weather
