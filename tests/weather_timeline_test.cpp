// Streamed weather tiles: where they land in the global map, across the antimeridian,
// and how keyframes blend over time so a new forecast never pops.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(WeatherTiles, ProblemsAreNamed) {
  EXPECT_TRUE(coverage_tile(40, 0, 50, 20, 0.5f).problem().empty());
  EXPECT_NE(coverage_tile(50, 0, 40, 20, 0.5f).problem(), "");
  EXPECT_NE(coverage_tile(40, -190, 50, 20, 0.5f).problem(), "");
  MapTile t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.data[3] = std::nanf("");
  EXPECT_NE(t.problem().find("finite"), std::string::npos);
  t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.data.pop_back();
  EXPECT_NE(t.problem().find("expected"), std::string::npos);
  t = coverage_tile(40, 0, 50, 20, 0.5f);
  t.channels = 0;
  EXPECT_NE(t.problem(), "");
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
  EXPECT_EQ(tl.keyframe_count(), 1u) << "keyframes in the past are dropped";
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
