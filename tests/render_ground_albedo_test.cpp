// The weather's ground albedo on the GPU (weather::Weather::ground_albedo): the ground's
// radiance and the light it sends up into a deck, with the round trips between them
// (ground_cloud_gain in shaders/slab_transmittance.glsl), as the CPU reference has them;
// the reference against the path-traced truth is tests/truth_ground_cloud_bounce_test.cpp.
// And the albedo that weather-map tiles set (weather/ground_albedo_map.h,
// shaders/ground_albedo.glsl): where they reach it is the global albedo of the same value.
#include <gtest/gtest.h>

#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"
#include "weather/ground_albedo_map.h"
#include "weather_tile_support.h"

namespace cloudsvc::test {
namespace {

double mean_green(const FrameImage& img) {
  double s = 0.0;
  for (int i = 0; i < img.width * img.height; ++i) s += img.rgba[4 * static_cast<std::size_t>(i) + 1];
  return s / (img.width * img.height);
}

TEST(GroundAlbedo, GpuFollowsTheReferenceOverSnowAndSea) {
  double ground[2] = {0.0, 0.0}, base[2] = {0.0, 0.0};
  const double albedos[2] = {0.8, 0.1};
  for (int k = 0; k < 2; ++k) {
    weather::Weather w = single_layer(weather::CloudType::Stratus, 400.0, 900.0, 1.0);
    w.ground_albedo = albedos[k];
    for (double pitch : {-90.0, 90.0}) {
      const ViewRequest v = make_view(47.45, 8.56, 100.0, 0.0, pitch, "2026-06-21T10:00Z", 8, 8, 10.0);
      const FrameImage ref = reference::render_reference(v, w, {});
      CloudRenderer& r = shared_renderer();
      r.set_weather(w);
      const FrameImage gpu = render_still_view(r, v, *quality_preset("default"));
      const double g = mean_green(gpu), e = mean_green(ref);
      std::printf("albedo %.1f, looking %s: GPU %.4f, reference %.4f (%+.2f %%)\n", albedos[k], pitch < 0 ? "down" : "up", g,
                  e, 100.0 * (g / e - 1.0));
      // the deck's base within 1 %; the ground within 5 %: its sun comes through the ground
      // shadow map's coarser march of the deck's optical depth (2-4 % dark here)
      EXPECT_NEAR(g, e, (pitch < 0 ? 0.05 : 0.01) * e);
      (pitch < 0 ? ground : base)[k] = g;
    }
  }
  // the round trips: over snow the ground is far more than 8 times as bright as over the sea
  EXPECT_GT(ground[0] / ground[1], 15.0);
  EXPECT_GT(base[0] / base[1], 1.7);
}

// Without a deck the ground's radiance follows its albedo (plus the air's path radiance).
TEST(GroundAlbedo, ClearSkyGroundFollowsTheAlbedo) {
  double g[2];
  const double albedos[2] = {0.8, 0.1};
  for (int k = 0; k < 2; ++k) {
    weather::Weather w;
    w.ground_albedo = albedos[k];
    const ViewRequest v = make_view(47.45, 8.56, 100.0, 0.0, -90.0, "2026-06-21T10:00Z", 8, 8, 10.0);
    const FrameImage ref = reference::render_reference(v, w, {});
    const FrameImage gpu = render_weather(w, v);
    g[k] = mean_green(gpu);
    EXPECT_NEAR(g[k], mean_green(ref), 0.03 * mean_green(ref));
  }
  std::printf("clear sky, snow / sea ground radiance: %.2f\n", g[0] / g[1]);
  EXPECT_NEAR(g[0] / g[1], 8.0, 0.5);
}

weather::MapTile albedo_tile(double lat0, double lon0, double lat1, double lon1, float albedo) {
  weather::MapTile t = coverage_tile(lat0, lon0, lat1, lon1, albedo);
  t.channels = weather::kGroundAlbedoTileChannel;
  return t;
}

// Under a stratus deck over the sea (global albedo 0.1), a tile of snow (0.8) over the view
// gives what a global albedo of 0.8 gives: the ground straight down and the deck's base
// straight up within 0.5 %; a tile elsewhere changes nothing. A renderer of its own: the
// tiles' albedo stays with a renderer across set_weather.
TEST(GroundAlbedo, TilesSetItWhereTheyReach) {
  CloudRenderer& shared = shared_renderer();  // creates the GL context
  CloudRenderer tiled;
  weather::Weather sea = single_layer(weather::CloudType::Stratus, 400.0, 900.0, 1.0);
  sea.ground_albedo = 0.1;
  weather::Weather snow = sea;
  snow.ground_albedo = 0.8;
  tiled.set_weather(sea);
  const double now = 0.0;
  tiled.apply_tile(albedo_tile(-40, 140, -30, 150, 0.8f), now);  // over Australia
  EXPECT_TRUE(tiled.ground_albedo_map().any());
  const RenderQuality q = *quality_preset("default");
  for (double pitch : {-90.0, 90.0}) {
    const ViewRequest v = make_view(47.45, 8.56, 100.0, 0.0, pitch, "2026-06-21T10:00Z", 8, 8, 10.0);
    shared.set_weather(sea);
    const double global_sea = mean_green(render_still_view(shared, v, q));
    shared.set_weather(snow);
    const double global_snow = mean_green(render_still_view(shared, v, q));
    const double far_tile = mean_green(render_still_view(tiled, v, q));
    EXPECT_NEAR(far_tile, global_sea, 1e-4 * global_sea) << "pitch " << pitch << ": a tile elsewhere";
    tiled.apply_tile(albedo_tile(46, 7, 49, 10, 0.8f), now);  // over Zurich
    const double near_tile = mean_green(render_still_view(tiled, v, q));
    std::printf("looking %s: global sea %.5f, snow %.5f; tile of snow elsewhere %.5f, over the view %.5f\n",
                pitch < 0 ? "down" : "up", global_sea, global_snow, far_tile, near_tile);
    EXPECT_NEAR(near_tile, global_snow, 0.005 * global_snow) << "pitch " << pitch;
    tiled.apply_tile(albedo_tile(46, 7, 49, 10, 0.1f), now);  // back to sea for the next view
  }
}

// From 60 km straight down, north up, over a tile edge at 8.56 E (snow to the west, the
// global sea albedo to the east): the image's western columns are those of a global snow
// albedo, its eastern ones those of the sea (the edge blends over one map texel, 0.35 deg
// of longitude, here the middle fifth of the image).
TEST(GroundAlbedo, TileEdgeFallsWhereItIs) {
  CloudRenderer& shared = shared_renderer();
  CloudRenderer tiled;
  weather::Weather sea;
  sea.ground_albedo = 0.1;
  weather::Weather snow = sea;
  snow.ground_albedo = 0.8;
  tiled.set_weather(sea);
  tiled.apply_tile(albedo_tile(40, 0, 55, 8.56, 0.8f), 0.0);
  const ViewRequest v = make_view(47.45, 8.56, 60000.0, 0.0, -90.0, "2026-06-21T10:00Z", 40, 8, 90.0);
  const FrameImage img = tiled.render(v, {});
  shared.set_weather(sea);
  const FrameImage img_sea = shared.render(v, {});
  shared.set_weather(snow);
  const FrameImage img_snow = shared.render(v, {});
  auto column_green = [](const FrameImage& im, int x) {
    double s = 0.0;
    for (int y = 0; y < im.height; ++y) s += im.rgba[4 * (static_cast<std::size_t>(y) * im.width + x) + 1];
    return s / im.height;
  };
  for (int x : {0, 3, 6, 9}) {
    EXPECT_NEAR(column_green(img, x), column_green(img_snow, x), 0.01 * column_green(img_snow, x)) << "column " << x;
    const int e = img.width - 1 - x;
    EXPECT_NEAR(column_green(img, e), column_green(img_sea, e), 0.01 * column_green(img_sea, e)) << "column " << e;
  }
  EXPECT_GT(column_green(img_snow, 0), 3.0 * column_green(img_sea, 0));  // the two differ
}

}  // namespace
}  // namespace cloudsvc::test
