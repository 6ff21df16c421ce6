// Streamed weather tiles: where they land in the global map, across the antimeridian,
// and how keyframes blend over time so a new forecast never pops.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "weather/map_tile.h"
#include "weather/weather_timeline.h"
#include "weather_tile_support.h"

namespace cloudsvc::weather {
namespace {

WeatherMap flat_map(float v, int w = 360, int h = 180) {
  WeatherMap m;
  m.width = w;
  m.height = h;
  m.rgba.assign(static_cast<std::size_t>(w) * h * 4, v);
  return m;
}

using test::coverage_tile;

float at(const WeatherMap& m, double lat, double lon, int ch = 0) {
  float v[4];
  m.sample(lat, lon, v);
  return v[ch];
}

TEST(WeatherTiles, ChangeOnlyTheirAreaAndChannels) {
  WeatherMap m = flat_map(0.5f);
  apply_tile(m, coverage_tile(40, 0, 50, 20, 0.9f));
  EXPECT_NEAR(at(m, 45, 10), 0.9f, 1e-6);
  EXPECT_NEAR(at(m, 45, 10, 1), 0.5f, 1e-6) << "other channels untouched";
  EXPECT_NEAR(at(m, 30, 10), 0.5f, 1e-6);
  EXPECT_NEAR(at(m, 45, 40), 0.5f, 1e-6);
}

TEST(WeatherTiles, CrossTheAntimeridian) {
  WeatherMap m = flat_map(0.5f);
  apply_tile(m, coverage_tile(-10, 170, 10, 200, 0.1f));  // 170E .. 160W
  EXPECT_NEAR(at(m, 0, 175), 0.1f, 1e-6);
  EXPECT_NEAR(at(m, 0, -175), 0.1f, 1e-6);
  EXPECT_NEAR(at(m, 0, -150), 0.5f, 1e-6);
  EXPECT_NEAR(at(m, 0, 160), 0.5f, 1e-6);
}

// One line naming the field (weather/map_tile.h; the protocol passes "WeatherMapTile.").
TEST(WeatherTiles, ProblemsAreNamed) {
  EXPECT_TRUE(coverage_tile(40, 0, 50, 20, 0.5f).problem().empty());
  EXPECT_EQ(coverage_tile(50, 0, 40, 20, 0.5f).problem(), "MapTile.lat_max_deg 40 out of range (50, 90]");
  EXPECT_EQ(coverage_tile(50, 0, 40, 20, 0.5f).problem("WeatherMapTile."),
            "WeatherMapTile.lat_max_deg 40 out of range (50, 90]");
  EXPECT_EQ(coverage_tile(40, -190, 50, 20, 0.5f).problem(), "MapTile.lon_min_deg -190 out of range [-180, 180)");
  EXPECT_EQ(coverage_tile(40, 170, 50, 530.5, 0.5f).problem(), "MapTile.lon_max_deg 530.5 out of range (170, 530]");
  EXPECT_EQ(coverage_tile(std::nan(""), 0, 50, 20, 0.5f).problem(), "MapTile.lat_min_deg is nan (must be finite)");
  MapTile t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.data[3] = std::nanf("");
  EXPECT_EQ(t.problem(), "MapTile.data[3] nan out of range [0, 1] (col 3, row 0, coverage)");
  t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.data.pop_back();
  EXPECT_EQ(t.problem(), "MapTile.data has 15 values, expected 16 (width 4 x height 4 x 1 channels)");
  t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.channels = 0;
  EXPECT_EQ(t.problem(), "MapTile.channels and layer_channels are empty");
  t.layer_channels = 0x01;  // the one value per texel is layer coverage slot 0
  EXPECT_TRUE(t.problem().empty());
  t.layer_channels = 0x11;
  EXPECT_EQ(t.problem(), "MapTile.layer_channels has unknown bits 0x10");
  t.layer_channels = 0;
  t.channels = 0x21;
  EXPECT_EQ(t.problem(), "MapTile.channels has unknown bits 0x20");
  t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.valid_at_utc_s = std::numeric_limits<double>::infinity();
  EXPECT_EQ(t.problem(), "MapTile.valid_at_utc_s is inf (must be finite)");
  // Several channels: the value's channel is named by its bit (0b101: coverage, density).
  t = coverage_tile(40, 0, 50, 20, 0.5f, 0.0, 2, 1);
  t.channels = 0b101;
  t.data = {0.5f, 0.5f, 0.5f, 1.25f};
  EXPECT_EQ(t.problem(), "MapTile.data[3] 1.25 out of range [0, 1] (col 1, row 0, density)");
  // Layer-coverage slots follow the channels in each texel (coverage, slot 1, slot 3).
  t.channels = 0b1;
  t.layer_channels = 0b1010;
  t.data = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, -0.5f};
  EXPECT_EQ(t.problem(), "MapTile.data[5] -0.5 out of range [0, 1] (col 1, row 0, layer coverage 3)");
  t.data.pop_back();
  EXPECT_EQ(t.problem(), "MapTile.data has 5 values, expected 6 (width 2 x height 1 x 3 channels)");
}

// Forecast weather streamed as tiles: the layer-coverage slots land in the map's layer
// coverage (a map without any gets it, 0 where no tile gave a value), in their area only,
// next to the tile's weather-map channels.
TEST(WeatherTiles, LayerCoverageSlotsLandInTheMapsLayerCoverage) {
  WeatherMap m = flat_map(0.5f);
  ASSERT_FALSE(m.has_layer_coverage());
  MapTile t = coverage_tile(40, 0, 50, 20, 0.9f, 0.0, 2, 2);
  t.layer_channels = 0b0101;  // slots 0 and 2 after the coverage channel
  t.data.clear();
  for (int texel = 0; texel < 4; ++texel) t.data.insert(t.data.end(), {0.9f, 0.25f, 0.75f});
  ASSERT_TRUE(t.problem().empty()) << t.problem();
  apply_tile(m, t);
  ASSERT_TRUE(m.has_layer_coverage());
  float c[4];
  m.sample_layer_coverage(45, 10, c);
  EXPECT_NEAR(c[0], 0.25f, 1e-6);
  EXPECT_NEAR(c[1], 0.0f, 1e-6) << "a slot the tile does not carry";
  EXPECT_NEAR(c[2], 0.75f, 1e-6);
  EXPECT_NEAR(c[3], 0.0f, 1e-6);
  EXPECT_NEAR(at(m, 45, 10), 0.9f, 1e-6) << "the coverage channel, before the slots";
  m.sample_layer_coverage(30, 10, c);
  EXPECT_NEAR(c[0], 0.0f, 1e-6) << "outside the tile";
  // A second tile with slot 2 only keeps slot 0.
  MapTile u = coverage_tile(40, 0, 50, 20, 0.0f, 0.0, 1, 1);
  u.channels = 0;
  u.layer_channels = 0b0100;
  u.data = {0.5f};
  apply_tile(m, u);
  m.sample_layer_coverage(45, 10, c);
  EXPECT_NEAR(c[0], 0.25f, 1e-6);
  EXPECT_NEAR(c[2], 0.5f, 1e-6);
  EXPECT_NEAR(at(m, 45, 10), 0.9f, 1e-6) << "no channels: the map's rgba untouched";
}

// The one size limit of a tile, whoever sends it (the protocol announces the same number).
TEST(WeatherTiles, AreAtMostKMaxTileTexelsASide) {
  EXPECT_EQ(kMaxTileTexels, 1024);
  EXPECT_TRUE(coverage_tile(40, 0, 50, 20, 0.5f, 0.0, kMaxTileTexels, 1).problem().empty());
  EXPECT_TRUE(coverage_tile(40, 0, 50, 20, 0.5f, 0.0, 1, kMaxTileTexels).problem().empty());
  EXPECT_EQ(coverage_tile(40, 0, 50, 20, 0.5f, 0.0, kMaxTileTexels + 1, 1).problem(),
            "MapTile.width 1025 out of range [1, 1024]");
  EXPECT_EQ(coverage_tile(40, 0, 50, 20, 0.5f, 0.0, 1, kMaxTileTexels + 1).problem(),
            "MapTile.height 1025 out of range [1, 1024]");
  EXPECT_EQ(coverage_tile(40, 0, 50, 20, 0.5f, 0.0, 0, 4).problem(), "MapTile.width 0 out of range [1, 1024]");
  MapTile t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.height = -3;
  EXPECT_EQ(t.problem(), "MapTile.height -3 out of range [1, 1024]");
}

// problem() is the header's rules, then the values'; the values may be held elsewhere.
TEST(WeatherTiles, HeaderAndDataRules) {
  MapTile t = coverage_tile(40, 0, 50, 20, 0.5f, 0.0, 2, 2);
  const std::vector<float> values{0.0f, 1.0f, 0.25f, -0.5f};
  t.data.clear();
  const MapTileHeader h = t.header();
  EXPECT_EQ(tile_header_problem(h, "T."), "");
  EXPECT_EQ(tile_data_problem(h, values, "T."), "T.data[3] -0.5 out of range [0, 1] (col 1, row 1, coverage)");
  EXPECT_EQ(tile_data_problem(h, std::span(values).first(3), "T."),
            "T.data has 3 values, expected 4 (width 2 x height 2 x 1 channels)");
  EXPECT_EQ(t.problem("T."), "T.data has 0 values, expected 4 (width 2 x height 2 x 1 channels)");
  // Sizes beyond int, as a message may send them, are named as sent.
  MapTileHeader wide = h;
  wide.width = 4294967295;
  EXPECT_EQ(tile_header_problem(wide, "T."), "T.width 4294967295 out of range [1, 1024]");
  t.lat_max_deg = 30;  // the header's problem comes first
  EXPECT_EQ(t.problem("T."), "T.lat_max_deg 30 out of range (40, 90]");
}

// A forecast valid in the future blends in linearly up to its valid-at time.
TEST(WeatherTimeline, FutureForecastBlendsIn) {
  WeatherTimeline tl(flat_map(0.5f));
  const double now = 1000.0;
  tl.apply(coverage_tile(40, 0, 50, 20, 0.9f, now + 600.0), now);
  EXPECT_EQ(tl.keyframe_count(), 2u);
  auto blend_at = [&](double t) {
    const auto b = tl.at(t);
    return at(*b.from, 45, 10) * (1 - b.weight) + at(*b.to, 45, 10) * b.weight;
  };
  EXPECT_NEAR(blend_at(now + 600.0 - 30.0 - 1.0), 0.5f, 1e-6) << "the base keyframe fades over the transition only";
  EXPECT_NEAR(blend_at(now + 600.0 - 15.0), 0.7f, 1e-5);
  EXPECT_NEAR(blend_at(now + 600.0), 0.9f, 1e-6);
  EXPECT_NEAR(blend_at(now + 900.0), 0.9f, 1e-6);
  EXPECT_NEAR(blend_at(now), 0.5f, 1e-6) << "going back shows the weather valid then";
}

double blended_coverage(const WeatherTimeline& tl, double t) {
  const auto b = tl.at(t);
  EXPECT_TRUE(b.from && b.to);
  EXPECT_TRUE(std::isfinite(b.weight) && b.weight >= 0.0f && b.weight <= 1.0f) << "t " << t;
  return at(*b.from, 45, 10) * (1 - b.weight) + at(*b.to, 45, 10) * b.weight;
}

// Three forecasts (10:30, 11:00, 11:30), a pose at 10:45, then one at 10:00 (a simulator
// that resets its clock): every time renders, before, between, after and far from the
// keyframes, in any order. Used to be undefined behaviour (std::prev of begin()) that hung
// the service's render thread.
TEST(WeatherTimeline, AnyTimeInAnyOrder) {
  const double t1030 = 37800.0, t1100 = 39600.0, t1130 = 41400.0;
  WeatherTimeline tl(flat_map(0.5f));
  const double now = 36000.0;  // 10:00
  tl.apply(coverage_tile(40, 0, 50, 20, 0.1f, t1030), now);
  tl.apply(coverage_tile(40, 0, 50, 20, 0.2f, t1100), now);
  tl.apply(coverage_tile(40, 0, 50, 20, 0.3f, t1130), now);
  ASSERT_EQ(tl.keyframe_count(), 4u);
  EXPECT_NEAR(blended_coverage(tl, 38700.0), 0.15f, 1e-5);  // 10:45
  EXPECT_NEAR(blended_coverage(tl, now), 0.5f, 1e-6);       // back to 10:00: the base map
  EXPECT_NEAR(blended_coverage(tl, t1130 + 1e6), 0.3f, 1e-6);
  EXPECT_NEAR(blended_coverage(tl, -1e12), 0.5f, 1e-6);
  EXPECT_NEAR(blended_coverage(tl, t1100), 0.2f, 1e-6);
  const double inf = std::numeric_limits<double>::infinity();
  for (double t : {std::nan(""), inf, -inf, 1e300, -1e300}) blended_coverage(tl, t);
}

// Past keyframes are dropped only at the limit, oldest first; a time before the oldest one
// kept uses it. Each new tile still lands (and is seen) at its valid-at time.
TEST(WeatherTimeline, BeforeTheOldestKeyframeKept) {
  WeatherTimeline tl(flat_map(0.5f));
  const std::size_t n = WeatherTimeline::kMaxKeyframes + 3;
  for (std::size_t i = 1; i <= n; ++i) {
    const double valid = 1000.0 * static_cast<double>(i);
    tl.apply(coverage_tile(40, 0, 50, 20, 0.05f * static_cast<float>(i), valid), valid - 1.0);
    EXPECT_LE(tl.keyframe_count(), WeatherTimeline::kMaxKeyframes);
    EXPECT_NEAR(blended_coverage(tl, valid), 0.05f * static_cast<float>(i), 1e-5);
  }
  EXPECT_EQ(tl.keyframe_count(), WeatherTimeline::kMaxKeyframes);
  const double oldest_kept = 0.05f * static_cast<float>(n - WeatherTimeline::kMaxKeyframes + 1);
  EXPECT_NEAR(blended_coverage(tl, 0.0), oldest_kept, 1e-5) << "before every keyframe: the oldest kept";
}

// A tile valid now (or earlier) does not pop: it arrives over the transition.
TEST(WeatherTimeline, LateTileDoesNotPop) {
  WeatherTimeline tl(flat_map(0.5f));
  const double now = 5000.0;
  tl.apply(coverage_tile(40, 0, 50, 20, 0.1f, now - 100.0), now);
  const auto b0 = tl.at(now);
  EXPECT_NEAR(at(*b0.from, 45, 10) * (1 - b0.weight) + at(*b0.to, 45, 10) * b0.weight, 0.5f, 1e-6);
  const auto b1 = tl.at(now + WeatherTimeline::kDefaultTransition_s);
  EXPECT_NEAR(at(*b1.from, 45, 10) * (1 - b1.weight) + at(*b1.to, 45, 10) * b1.weight, 0.1f, 1e-6);
}

// Versions change exactly when a keyframe changes (drives GPU re-uploads).
TEST(WeatherTimeline, VersionsTrackChanges) {
  WeatherTimeline tl(flat_map(0.5f));
  const auto a = tl.at(0.0);
  const auto b = tl.at(1.0);
  EXPECT_EQ(a.from_version, b.from_version);
  tl.apply(coverage_tile(40, 0, 50, 20, 0.9f, 100.0), 0.0);
  const auto c = tl.at(1.0);
  EXPECT_NE(c.to_version, c.from_version);
}

}  // namespace
}  // namespace cloudsvc::weather
