// The weather's ground albedo on the GPU (weather::Weather::ground_albedo): the ground's
// radiance and the light it sends up into a deck, with the round trips between them
// (ground_cloud_gain in shaders/slab_transmittance.glsl), as the CPU reference has them;
// the reference against the path-traced truth is tests/truth_ground_cloud_bounce_test.cpp.
#include <gtest/gtest.h>

#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/reference_renderer.h"

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

}  // namespace
}  // namespace cloudsvc::test
