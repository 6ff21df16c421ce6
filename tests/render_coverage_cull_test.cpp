// Layers with no cloud within a frame's reach are not marched (renderer/coverage_cull.h):
// the cap scan finds a single cloudy texel wherever it is inside the cap (across the
// antimeridian, over a pole) and none outside it; a frame whose layer the weather map
// clears around the camera marches nothing and looks exactly like a clear sky, and one
// with cloud just inside the cap still marches the layer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geodesy/geodetic.h"
#include "render_test_support.h"
#include "renderer/coverage_cull.h"
#include "weather/weather_map.h"
#include "weather/weather_timeline.h"

namespace cloudsvc::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 720x360 map (0.5 deg texels), coverage modulation 0 except m at the texel containing
// (lat, lon).
weather::WeatherMap one_cloudy_texel(double lat, double lon, float m) {
  weather::WeatherMap map;
  map.width = 720;
  map.height = 360;
  map.rgba.assign(static_cast<size_t>(map.width) * map.height * 4, 0.0f);
  const int i = static_cast<int>(std::floor((lon + 180.0) / 0.5)) % map.width;
  const int j = std::min(map.height - 1, static_cast<int>(std::floor((lat + 90.0) / 0.5)));
  map.rgba[(static_cast<size_t>(j) * map.width + i) * 4] = m;
  return map;
}

TEST(CoverageCull, CapScanFindsACloudyTexelOnlyInsideTheCap) {
  const double cap = 300e3 / 6371e3;  // 300 km: 2.7 deg
  // due north of the camera, inside and (well) outside the cap
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(47.0 + 2.0, 8.0, 0.7f), 47.0, 8.0, cap), 0.7f);
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(47.0 + 5.0, 8.0, 0.7f), 47.0, 8.0, cap), 0.0f);
  // east at 47 N: 2.7 deg of arc is 4 deg of longitude there
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(47.0, 8.0 + 3.6, 0.7f), 47.0, 8.0, cap), 0.7f);
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(47.0, 8.0 + 6.0, 0.7f), 47.0, 8.0, cap), 0.0f);
  // across the antimeridian
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(0.0, -179.0, 0.4f), 0.0, 179.5, cap), 0.4f);
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(0.0, 179.0, 0.4f), 0.0, -179.5, cap), 0.4f);
  // over the pole: the other side of the pole is within the cap
  EXPECT_FLOAT_EQ(max_coverage_in_cap(one_cloudy_texel(89.0, -170.0, 0.9f), 89.0, 10.0, cap), 0.9f);
  // a non-finite texel counts as cloud
  weather::WeatherMap bad = one_cloudy_texel(47.0, 8.0, 0.0f);
  bad.rgba[(static_cast<size_t>(274) * bad.width + 376) * 4] = NAN;
  EXPECT_FLOAT_EQ(max_coverage_in_cap(bad, 47.0, 8.0, cap), 1.0f);
}

TEST(CoverageCull, CapIsTheReachWithMarginPlusTheLightMarch) {
  const double R = 6371e3;
  EXPECT_NEAR(cloud_influence_cap_rad(R, 200e3) * R, 1.01 * 200e3 + 4000.0, 1.0);
  EXPECT_LE(cloud_influence_cap_rad(R, 1e8), kPi);
}

// Scattered cumulus (one layer, coverage 0.35, which the map can clear) over Zurich with the weather map's coverage set to 0 over 38-57 N, 5 W-22 E
// (1.5 deg from the camera at least: beyond the reach at 1500 m, its 10 % hysteresis and
// the 4 km light march); then the same with a cloudy patch 1 deg from the camera.
TEST(CoverageCull, AFrameWhoseLayerHasNoCloudInReachMarchesNothing) {
  CloudRenderer& r = shared_renderer();
  const ViewRequest v = make_view(47.45, 8.56, 1500.0, 200.0, 5.0, "2026-06-21T11:30:00Z", 96, 54);
  r.set_weather(*weather::preset("clear"));
  const FrameImage clear = r.render(v);

  auto tile_around = [&](float m_patch) {
    weather::MapTile t;
    t.lat_min_deg = 38.0;
    t.lat_max_deg = 57.0;
    t.lon_min_deg = -5.0;
    t.lon_max_deg = 22.0;
    t.width = 108;  // 0.25 deg
    t.height = 76;
    t.channels = 1;
    t.valid_at_utc_s = v.unix_time_s - 3600.0;
    t.data.assign(static_cast<size_t>(t.width) * t.height, 0.0f);
    // a 0.5 x 0.5 deg patch centred ~1 deg north-west of the camera
    for (int j = 40; j < 42; ++j)  // 48.0-48.5 N
      for (int i = 49; i < 51; ++i) t.data[static_cast<size_t>(j) * t.width + i] = m_patch;  // 7.25-7.75 E
    return t;
  };

  r.set_weather(*weather::preset("scattered-cumulus"));
  r.apply_tile(tile_around(0.0f), v.unix_time_s - 3600.0);
  const FrameImage first = r.render(v);
  EXPECT_TRUE(first.stats.shadow_map_rebuilt);
  EXPECT_EQ(first.stats.density_evals_per_pixel, 0.0);  // the shadow map skips the culled layer too
  const FrameImage culled = r.render(v);
  EXPECT_EQ(culled.stats.layers_without_cloud_in_view, 1);
  EXPECT_EQ(culled.stats.density_evals_per_pixel, 0.0);  // nothing marched (shadow map not rebuilt)
  EXPECT_EQ(culled.stats.cloud_pixels, 0);
  double worst = 0.0;
  for (size_t k = 0; k < clear.rgba.size(); ++k)
    worst = std::max(worst, std::abs(static_cast<double>(culled.rgba[k]) - clear.rgba[k]) / (std::abs(clear.rgba[k]) + 1e-4));
  std::printf("culled layer vs clear sky: worst relative difference %.2e (first frame %d layers culled)\n", worst,
              first.stats.layers_without_cloud_in_view);
  EXPECT_LT(worst, 1e-5);

  // The patch is inside the cap, so the layer is kept; it is behind the camera, so no ray
  // of the view passes through it: the march finds cloud nowhere. Without the coverage
  // pyramid it evaluates the layer's density along every ray; with it (the default) the
  // pyramid clears every run of steps (renderer/coverage_pyramid.h).
  RenderQuality no_pyramid;
  no_pyramid.coverage_pyramid = false;
  r.set_weather(*weather::preset("scattered-cumulus"));
  r.apply_tile(tile_around(1.0f), v.unix_time_s - 3600.0);
  r.render(v, no_pyramid);
  const FrameImage kept = r.render(v, no_pyramid);
  EXPECT_EQ(kept.stats.layers_without_cloud_in_view, 0);
  EXPECT_GT(kept.stats.density_evals_per_pixel, 0.0);
  EXPECT_EQ(kept.stats.cloud_pixels, 0);
  RenderQuality with_pyramid = no_pyramid;
  with_pyramid.coverage_pyramid = true;
  const FrameImage skipped = r.render(v, with_pyramid);
  EXPECT_EQ(skipped.stats.layers_without_cloud_in_view, 0);
  EXPECT_EQ(skipped.stats.density_evals_per_pixel, 0.0);
  EXPECT_EQ(skipped.rgba, kept.rgba);  // the same image: nothing skipped had cloud
}

}  // namespace
}  // namespace cloudsvc::test
