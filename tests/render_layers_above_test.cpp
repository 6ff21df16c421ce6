// The light a layer receives through the layers above it (shaders/layers_above.glsl, its
// twin reference::layers_above_light; docs/RENDERING.md "Layers above"): a deck above a
// cumulus field shades it and passes on diffuse light, the GPU and the reference alike.
#include <gtest/gtest.h>

#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_lighting.h"
#include "renderer/reference/image_metrics.h"
#include "renderer/reference/reference_renderer.h"
#include "weather/presets.h"

namespace cloudsvc::test {
namespace {

// The factors of layers_above_light: nothing above lets everything through; the direct beam
// falls as e^-tau; the light that gets through as a whole (direct + diffuse) is the slab's
// beam transmittance, more of it arriving diffuse the thicker the deck; a bright layer below
// gains from the round trips under the deck.
TEST(LayersAbove, TheDeckPassesTheSlabsLightOn) {
  using reference::layers_above_light;
  const reference::LightFromAbove none = layers_above_light(0.0, 0.6, 0.5);
  EXPECT_EQ(none.direct, 1.0);
  EXPECT_EQ(none.sky, 1.0);
  EXPECT_EQ(none.sun_diffuse, 0.0);
  const double mu = 0.6;
  for (double tau_v : {0.5, 2.0, 8.0, 30.0}) {
    const double tau = tau_v / mu;  // slant
    const reference::LightFromAbove dark = layers_above_light(tau, mu, 0.0);
    EXPECT_NEAR(dark.direct, std::exp(-tau), 1e-12);
    EXPECT_NEAR(dark.direct + dark.sun_diffuse, model::slab_beam_transmittance(tau_v, mu), 1e-12);
    EXPECT_NEAR(dark.sky, model::slab_diffuse_transmittance(tau_v), 1e-12);
    const reference::LightFromAbove bright = layers_above_light(tau, mu, 0.7);
    EXPECT_GT(bright.sky, dark.sky);
    EXPECT_GT(bright.sun_diffuse, dark.sun_diffuse);
    EXPECT_EQ(bright.direct, dark.direct);  // the round trips return light diffuse, not in the beam
    // the light between the two can never exceed what a reflector under the deck gathers
    // from an infinite series: T / (1 - r R) with r, R < 1
    EXPECT_LT(bright.sky, 1.0 / (1.0 - 0.7));
  }
  // thick: almost all of what gets through arrives diffuse
  const reference::LightFromAbove thick = layers_above_light(30.0 / mu, mu, 0.0);
  EXPECT_GT(thick.sun_diffuse, 1e6 * thick.direct);
}

// w with an altostratus deck at 4.0-4.8 km over 90 % of the sky above its layers.
weather::Weather with_deck(weather::Weather w) {
  weather::CloudLayer deck = weather::default_layer(weather::CloudType::Altostratus);
  deck.base_m = 4000.0;
  deck.top_m = 4800.0;
  deck.coverage = 0.9;
  w.layers.push_back(deck);
  return w;
}

// Scattered cumulus seen from 3.2 km, between it and an altostratus deck (4.0-4.8 km, 90 %)
// under a sun 40 degrees high: the deck darkens the view by the share the two renderers
// agree on, and the GPU stays as close to the reference with the deck as without it.
TEST(LayersAbove, ADeckShadesTheLayerBelowAndSendsItsLightDown) {
  const weather::Weather cumulus = *weather::preset("scattered-cumulus");
  const weather::Weather decked = with_deck(cumulus);
  const ViewRequest v = make_view(47.45, 8.56, 3200.0, 135.0, -20.0, "2026-06-21T08:00Z", 32, 18, 60.0);
  const reference::ReferenceSettings settings;
  CloudRenderer& r = shared_renderer();
  const RenderQuality q = *quality_preset("default");
  double gpu_mean[2], ref_mean[2], err[2];
  int i = 0;
  for (const weather::Weather* w : {&cumulus, static_cast<const weather::Weather*>(&decked)}) {
    const FrameImage ref = reference::render_reference(v, *w, settings);
    r.set_weather(*w);
    const FrameImage gpu = render_still_view(r, v, q);
    EXPECT_EQ(gpu.stats.nonfinite_pixels, 0);
    maybe_save(i ? "layers_above_deck_gpu" : "layers_above_open_gpu", gpu);
    gpu_mean[i] = mean_luminance(gpu);
    ref_mean[i] = mean_luminance(ref);
    err[i] = reference::compare_images(gpu, ref).relative_rmse;
    ++i;
  }
  const double gpu_ratio = gpu_mean[1] / gpu_mean[0], ref_ratio = ref_mean[1] / ref_mean[0];
  std::printf("GPU vs reference: open %.3f, under the deck %.3f; the deck darkens the view to %.3f (GPU), %.3f "
              "(reference)\n",
              err[0], err[1], gpu_ratio, ref_ratio);
  // the deck's shade is strong and the two renderers draw the same
  EXPECT_LT(ref_ratio, 0.85);
  EXPECT_NEAR(gpu_ratio, ref_ratio, 0.03);
  EXPECT_LT(err[1], err[0] + 0.02);
}

// Looking up from under the cumulus no ray sees the ground, yet the cumulus samples read the
// deck's light from the ground shadow map: it is built for them, and reading it costs no
// density evaluation (a march of the deck per sample would).
TEST(LayersAbove, TheMapIsBuiltForALayerUnderAnotherWithoutGroundInView) {
  const weather::Weather cumulus = *weather::preset("scattered-cumulus");
  const weather::Weather decked = with_deck(cumulus);
  const ViewRequest v = make_view(47.45, 8.56, 600.0, 135.0, 45.0, "2026-06-21T08:00Z", 32, 18, 60.0);
  RenderQuality q = *quality_preset("default");
  RenderQuality per_sample = q;
  per_sample.ground_shadow_map = false;  // no map: each upper layer marched from every sample
  CloudRenderer& open_sky = shared_renderer();  // (creates the GL context the other two share)
  CloudRenderer with_map, without_map;
  open_sky.set_weather(cumulus);
  with_map.set_weather(decked);
  without_map.set_weather(decked);
  ViewRequest fresh = v;
  fresh.reset_history = true;  // the shared renderer may hold a map of another view
  const FrameImage a = open_sky.render(fresh, q);
  const FrameImage b = with_map.render(v, q);
  without_map.render(v, per_sample);
  // the next frame, 1 s later: the map is kept (evaluations of the march alone)
  ViewRequest next = v;
  next.unix_time_s += 1.0;
  next.frame_index = 1;
  const FrameImage b1 = with_map.render(next, q);
  const FrameImage c1 = without_map.render(next, per_sample);
  std::printf("map rebuilt: open sky %d, under the deck %d; next frame's evals/px with the map %.2f, marched per "
              "sample %.2f\n",
              a.stats.shadow_map_rebuilt, b.stats.shadow_map_rebuilt, b1.stats.density_evals_per_pixel,
              c1.stats.density_evals_per_pixel);
  EXPECT_FALSE(a.stats.shadow_map_rebuilt);  // nothing reads it
  EXPECT_TRUE(b.stats.shadow_map_rebuilt);
  EXPECT_FALSE(b1.stats.shadow_map_rebuilt);
  EXPECT_LT(b1.stats.density_evals_per_pixel, c1.stats.density_evals_per_pixel);
  EXPECT_EQ(b1.stats.nonfinite_pixels, 0);
}

}  // namespace
}  // namespace cloudsvc::test
