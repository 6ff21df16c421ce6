// The coverage max-pyramid (renderer/coverage_pyramid.h) and the march's per-run skip
// (shaders/coverage_pyramid.glsl): the pyramid's bound is never below what the map gives
// anywhere in the cap (across the antimeridian, over the poles, for a blend of two
// keyframes), it finds a single cloudy texel and nothing beyond it; a view over a forecast
// that is clear over part of the view marches fewer samples and gives the same image
// (bit for bit without long steps, within float noise with the default preset's).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "render_test_support.h"
#include "weather_tile_support.h"
#include "renderer/coverage_pyramid.h"
#include "renderer/quality_presets.h"
#include "weather/weather_map.h"
#include "weather/weather_timeline.h"

namespace cloudsvc::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// The largest map value at n random points within angular distance cap of (lat, lon), rad;
// blend_with: a second keyframe blended at a random weight per point.
float sampled_max(const weather::WeatherMap& map, const weather::WeatherMap* blend_with, double lat, double lon,
                  double cap, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double c[3] = {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
  // tangent basis at c
  double e[3] = {-std::sin(lon), std::cos(lon), 0.0};
  const double nn[3] = {-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
  float best = 0.0f;
  for (int k = 0; k < n; ++k) {
    const double th = cap * std::sqrt(u(rng)), az = 2.0 * kPi * u(rng);
    double p[3];
    for (int i = 0; i < 3; ++i)
      p[i] = std::cos(th) * c[i] + std::sin(th) * (std::cos(az) * e[i] + std::sin(az) * nn[i]);
    const double plat = std::atan2(p[2], std::hypot(p[0], p[1])), plon = std::atan2(p[1], p[0]);
    float v[4];
    map.sample(plat / kDeg, plon / kDeg, v);
    float m = v[0];
    if (blend_with) {
      float w[4];
      blend_with->sample(plat / kDeg, plon / kDeg, w);
      m += static_cast<float>(u(rng)) * (w[0] - m);
    }
    best = std::max(best, m);
  }
  return best;
}

TEST(CoveragePyramid, BoundIsNeverBelowTheMapAnywhereInTheCap) {
  const weather::WeatherMap a = weather::generate_procedural_map(21, 256, 128);
  const weather::WeatherMap b = weather::generate_procedural_map(22, 256, 128);
  const CoveragePyramid single = build_coverage_pyramid(a);
  const CoveragePyramid both = build_coverage_pyramid(a, &b);
  ASSERT_EQ(single.levels.front().width, 256);
  ASSERT_EQ(single.levels.front().height, 129);
  ASSERT_EQ(single.levels.back().width, 1);
  ASSERT_EQ(single.levels.back().height, 1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int caps = 0;
  double slack = 0.0, global_slack = 0.0;  // sum of (bound - sampled max), of (map max - sampled max)
  for (int k = 0; k < 400; ++k) {
    // caps everywhere, a tenth of them at the poles or the antimeridian
    double lat = (u(rng) - 0.5) * kPi, lon = (u(rng) - 0.5) * 2.0 * kPi;
    if (k % 10 == 1) lat = (u(rng) < 0.5 ? -1.0 : 1.0) * (0.5 * kPi - 0.02 * u(rng));
    if (k % 10 == 2) lon = (u(rng) < 0.5 ? -1.0 : 1.0) * (kPi - 0.02 * u(rng));
    const double cap = std::exp(std::log(1e-4) + u(rng) * (std::log(0.3) - std::log(1e-4)));  // 0.6 km .. 1900 km
    const float bound = pyramid_max_in_cap(single, lat, lon, cap);
    const float seen = sampled_max(a, nullptr, lat, lon, cap, 200, rng);
    ASSERT_GE(bound, seen) << "lat " << lat / kDeg << " lon " << lon / kDeg << " cap " << cap;
    ASSERT_GE(pyramid_max_in_cap(both, lat, lon, cap), sampled_max(a, &b, lat, lon, cap, 200, rng));
    slack += bound - seen;
    global_slack += single.cells.back() - seen;
    ++caps;
  }
  std::printf("mean bound - sampled maximum over %d caps: %.3f (map maximum - sampled: %.3f)\n", caps, slack / caps,
              global_slack / caps);
  EXPECT_LT(slack, 0.5 * global_slack);  // the bound reads the cap's own cells, not the whole map
}

// A map clear (m = 0) except one texel of m = 0.8 at (lat, lon), 0.5 deg texels.
weather::WeatherMap one_cloudy_texel(double lat_deg, double lon_deg) {
  weather::WeatherMap map;
  map.width = 720;
  map.height = 360;
  map.rgba.assign(static_cast<size_t>(map.width) * map.height * 4, 0.0f);
  const int i = static_cast<int>(std::floor((lon_deg + 180.0) / 0.5)) % map.width;
  const int j = static_cast<int>(std::floor((lat_deg + 90.0) / 0.5));
  map.rgba[(static_cast<size_t>(j) * map.width + i) * 4] = 0.8f;
  return map;
}

TEST(CoveragePyramid, FindsASingleCloudyTexelAndNothingBeyondIt) {
  const double km = 1e3 / 6371e3;  // rad per km on the sphere
  {
    const CoveragePyramid p = build_coverage_pyramid(one_cloudy_texel(47.25, 8.25));
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 47.25 * kDeg, 8.25 * kDeg, 1.0 * km), 0.8f);
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 47.25 * kDeg, 8.25 * kDeg, 500.0 * km), 0.8f);
    // 1.5 deg (167 km) north, caps of 50 km: two texels' bilinear reach away
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 48.75 * kDeg, 8.25 * kDeg, 50.0 * km), 0.0f);
    // 80 km east (1.06 deg of longitude at 47 N) with a 40 km cap: not reached
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 47.25 * kDeg, 9.5 * kDeg, 30.0 * km), 0.0f);
  }
  {  // across the antimeridian
    const CoveragePyramid p = build_coverage_pyramid(one_cloudy_texel(0.25, 179.75));
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 0.25 * kDeg, -179.8 * kDeg, 30.0 * km), 0.8f);
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 0.25 * kDeg, -178.0 * kDeg, 30.0 * km), 0.0f);
  }
  {  // the pole value (row mean) counts near the pole, for every longitude
    const CoveragePyramid p = build_coverage_pyramid(one_cloudy_texel(89.75, 100.25));
    EXPECT_GT(pyramid_max_in_cap(p, 89.9 * kDeg, -80.0 * kDeg, 5.0 * km), 0.0f);
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 85.0 * kDeg, -80.0 * kDeg, 50.0 * km), 0.0f);
  }
  {  // a non-finite texel counts as cloud
    weather::WeatherMap bad = one_cloudy_texel(0.25, 0.25);
    bad.rgba[(static_cast<size_t>(200) * bad.width + 400) * 4] = NAN;  // 10.25 N 20.25 E
    const CoveragePyramid p = build_coverage_pyramid(bad);
    EXPECT_FLOAT_EQ(pyramid_max_in_cap(p, 10.25 * kDeg, 20.25 * kDeg, 5.0 * km), 1.0f);
  }
  weather::WeatherMap other = one_cloudy_texel(0.0, 0.0);
  other.width = 360;
  EXPECT_THROW(build_coverage_pyramid(one_cloudy_texel(0.0, 0.0), &other), std::invalid_argument);
}

// Worst per-channel difference of a from b relative to b (floor 1e-4).
double worst_relative(const FrameImage& a, const FrameImage& b) {
  double worst = 0.0;
  for (size_t k = 0; k < a.rgba.size(); ++k)
    worst = std::max(worst, std::abs(static_cast<double>(a.rgba[k]) - b.rgba[k]) / (std::abs(b.rgba[k]) + 1e-4));
  return worst;
}

// A coverage tile of value m over lat0..lat1 (46..49 by default), lon0..lon1, 50 x 30 texels.
weather::MapTile coverage_tile(double lon0, double lon1, float m, double valid_at, double lat0 = 46.0,
                               double lat1 = 49.0) {
  return test::coverage_tile(lat0, lon0, lat1, lon1, m, valid_at, 50, 30);
}

// The second frame of view v after set_weather(scattered cumulus) and forecast(r): a full
// march (quality without temporal reuse) or the preset's 1/16 on top of its history; the
// first frame builds the shadow map, which the pyramid does not serve.
template <class Forecast>
FrameImage second_frame(const ViewRequest& v, RenderQuality q, bool pyramid, Forecast forecast) {
  CloudRenderer& r = shared_renderer();
  q.coverage_pyramid = pyramid;
  r.set_weather(*weather::preset("scattered-cumulus"));
  forecast(r);
  r.render(v, q);
  return r.render(v, q);
}

// Scattered cumulus (1200-2600 m, coverage 0.35, which the map clears where m < 1/12) seen
// from 12 km, looking 15 deg down: the rays meet the layer from ~17 km (the bottom of the
// view) to beyond 100 km (near the horizon) out. A forecast tile sets m = 0 from 42 km
// ahead of the camera on (the 0.35 deg texels of the renderer's map and their bilinear reach
// put the clear edge some 20-50 km farther) and leaves the map's own values elsewhere: the
// far half of the view's layer is clear. Over Zurich looking west, and on the equator
// looking east across the antimeridian (the clear tile on the far side of it, a cloudier
// one, m = 0.7, on the camera's side: the procedural map is sparse there).
struct ClearAhead {
  const char* name;
  double lat, lon, heading;
  double clear_lon0, clear_lon1, clear_lat0, clear_lat1;
  double cloudy_lon0 = 0.0, cloudy_lon1 = 0.0;  // a tile of m = 0.7 over the same latitudes (if lon1 > lon0)
};

class CoveragePyramidView : public ::testing::TestWithParam<ClearAhead> {};

TEST_P(CoveragePyramidView, AViewOverAPartlyClearForecastMarchesLessForTheSameImage) {
  const ClearAhead& c = GetParam();
  const ViewRequest v = make_view(c.lat, c.lon, 12000.0, c.heading, -15.0, "2026-06-21T11:30:00Z", 96, 54);
  auto forecast = [&](CloudRenderer& r) {
    r.apply_tile(coverage_tile(c.clear_lon0, c.clear_lon1, 0.0f, v.unix_time_s - 3600.0, c.clear_lat0, c.clear_lat1),
                 v.unix_time_s - 3600.0);
    if (c.cloudy_lon1 > c.cloudy_lon0)
      r.apply_tile(coverage_tile(c.cloudy_lon0, c.cloudy_lon1, 0.7f, v.unix_time_s - 3600.0, c.clear_lat0, c.clear_lat1),
                   v.unix_time_s - 3600.0);
  };
  // every step evaluated (no long steps): the skipped samples are exactly the zero ones
  RenderQuality full;
  full.long_step_factor = 1;
  const FrameImage off = second_frame(v, full, false, forecast), on = second_frame(v, full, true, forecast);
  ASSERT_GT(off.stats.cloud_pixels, 50);
  const double worst_full = worst_relative(on, off);
  // the default preset (long steps x4, its second frame: 1/16 of the pixels, the rest
  // reprojected): a skip can shift the phase of the long-step probes after it, which the
  // probes' bound makes harmless; the image is required to stay within float noise of the
  // march without the pyramid. The probes already take the empty runs at a quarter of the
  // cost, so the pyramid saves less there (1.7 -> 1.4 evaluations per pixel, 2026-12-02)
  const RenderQuality preset = *quality_preset("default");
  const FrameImage d_off = second_frame(v, preset, false, forecast), d_on = second_frame(v, preset, true, forecast);
  const double worst_default = worst_relative(d_on, d_off);
  std::printf("%s: density evaluations per pixel: every step %.1f -> %.1f (worst relative difference %.1e), "
              "default %.1f -> %.1f (%.1e)\n",
              c.name, off.stats.density_evals_per_pixel, on.stats.density_evals_per_pixel, worst_full,
              d_off.stats.density_evals_per_pixel, d_on.stats.density_evals_per_pixel, worst_default);
  EXPECT_EQ(worst_full, 0.0);
  EXPECT_LT(on.stats.density_evals_per_pixel, 0.8 * off.stats.density_evals_per_pixel);
  EXPECT_LT(worst_default, 1e-3);
  EXPECT_LT(d_on.stats.density_evals_per_pixel, 0.9 * d_off.stats.density_evals_per_pixel);
  EXPECT_EQ(on.stats.cloud_pixels, off.stats.cloud_pixels);
}

INSTANTIATE_TEST_SUITE_P(
    Places, CoveragePyramidView,
    ::testing::Values(ClearAhead{"Zurich_looking_west", 47.45, 8.56, 270.0, 3.0, 8.0, 46.0, 49.0},
                      ClearAhead{"equator_looking_east_across_the_antimeridian", 0.0, 179.9, 90.0, -179.95, -175.0, -1.5,
                                 1.5, 178.0, 179.99}),
    [](const ::testing::TestParamInfo<ClearAhead>& info) { return std::string(info.param.name); });

// A clear keyframe now and a cloudy one 10 minutes ahead that fades in: at the view's time
// the map is a blend of the two, mostly the cloudy one. The pyramid is the maximum over both
// keyframes, so nothing that the blend makes cloudy is skipped (a pyramid of the first
// keyframe alone would skip all of it).
TEST(CoveragePyramid, ABlendTowardsACloudyKeyframeIsNotSkipped) {
  const ViewRequest v = make_view(47.45, 8.56, 12000.0, 270.0, -15.0, "2026-06-21T11:30:00Z", 96, 54);
  auto forecast = [&](CloudRenderer& r) {
    r.apply_tile(coverage_tile(3.0, 12.0, 0.0f, v.unix_time_s - 7200.0), v.unix_time_s - 7200.0);
    r.apply_tile(coverage_tile(3.0, 12.0, 0.9f, v.unix_time_s + 600.0), v.unix_time_s - 7140.0);
  };
  RenderQuality full;
  full.long_step_factor = 1;
  const FrameImage off = second_frame(v, full, false, forecast), on = second_frame(v, full, true, forecast);
  std::printf("blend into a cloudy keyframe: %lld cloud pixels, evaluations per pixel %.1f -> %.1f\n",
              static_cast<long long>(off.stats.cloud_pixels), off.stats.density_evals_per_pixel,
              on.stats.density_evals_per_pixel);
  ASSERT_GT(off.stats.cloud_pixels, 500);
  EXPECT_EQ(worst_relative(on, off), 0.0);
  EXPECT_EQ(on.stats.cloud_pixels, off.stats.cloud_pixels);
}

}  // namespace
}  // namespace cloudsvc::test
