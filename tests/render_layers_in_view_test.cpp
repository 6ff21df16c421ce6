// A frame whose rays meet no cloud layer marches nothing (renderer/layers_in_view.h, issue 5:
// "a frame above a solid deck looking up costs no cloud march at all"): the frustum's range
// of zenith cosines is exact, the skipped frame is the clear sky bit for bit, and the next
// frame that does see the deck has no trace of the empty buffer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "render_test_support.h"
#include "renderer/layers_in_view.h"
#include "renderer/quality_presets.h"

namespace cloudsvc::test {
namespace {

// Brute force over a fine grid of rays: the exact range contains every sampled mu and is
// within the grid's resolution of the sampled extremes.
TEST(LayersInView, FrustumMuRangeMatchesBruteForce) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  double worst_outside = 0.0, worst_gap = 0.0;
  for (int k = 0; k < 300; ++k) {
    glm::dvec3 f = glm::normalize(glm::dvec3(uni(rng), uni(rng), uni(rng)));
    if (k % 10 == 0) f = glm::normalize(glm::dvec3(uni(rng) * 1e-3, uni(rng) * 1e-3, k % 20 == 0 ? 1.0 : -1.0));  // near zenith / nadir
    glm::dvec3 side = glm::cross(f, glm::dvec3(0.3, -0.7, 0.2));
    const glm::dvec3 r = glm::normalize(side), u = glm::cross(r, f);
    const double tx = std::tan((5.0 + 55.0 * (uni(rng) + 1.0)) * M_PI / 360.0), ty = tx * (0.3 + 0.35 * (uni(rng) + 1.0));
    const MuRange m = frustum_mu_range(f, r, u, tx, ty);
    double lo = 1.0, hi = -1.0;
    const int n = 200;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double z = glm::normalize(f + (2.0 * i / n - 1.0) * tx * r + (2.0 * j / n - 1.0) * ty * u).z;
        lo = std::min(lo, z);
        hi = std::max(hi, z);
      }
    worst_outside = std::max({worst_outside, m.min - lo, hi - m.max});
    worst_gap = std::max({worst_gap, lo - m.min, m.max - hi});
  }
  std::printf("frustum mu range vs 201x201 rays: sampled beyond the range by %.2e, range beyond the samples by %.2e\n",
              worst_outside, worst_gap);
  EXPECT_LE(worst_outside, 1e-12);
  EXPECT_LT(worst_gap, 1e-3);
}

TEST(LayersInView, AboveTheDeckLookingUpMarchesNothingAndIsTheClearSky) {
  CloudRenderer& r = shared_renderer();
  // overcast stratus 400-900 m; camera at 1500 m
  ViewRequest up = make_view(47.45, 8.56, 1500.0, 200.0, 25.0, "2026-06-21T11:30:00Z", 64, 36);
  up.reset_history = true;
  r.set_weather(*weather::preset("overcast-stratus"));
  const FrameImage deck_up = r.render(up, *quality_preset("default"));
  EXPECT_EQ(deck_up.stats.marched_fraction, 0.0);
  EXPECT_EQ(deck_up.stats.density_evals_per_pixel, 0.0);  // no march, and no shadow map: no ground in view
  EXPECT_FALSE(deck_up.stats.shadow_map_rebuilt);
  r.set_weather(*weather::preset("clear"));
  const FrameImage clear_up = r.render(up, *quality_preset("default"));
  ASSERT_EQ(deck_up.rgba.size(), clear_up.rgba.size());
  size_t differ = 0;
  for (size_t i = 0; i < deck_up.rgba.size(); ++i) differ += deck_up.rgba[i] != clear_up.rgba[i] ? 1 : 0;
  EXPECT_EQ(differ, 0u) << "the skipped frame is the clear sky";
  // Level flight at the same place: the lower image edge sees the deck (1500 m up, 8.7 deg
  // below the horizontal at the bottom of a 60x34 deg view): marched.
  r.set_weather(*weather::preset("overcast-stratus"));
  ViewRequest level = up;
  level.attitude.pitch_deg = 0.0;
  level.reset_history = true;
  EXPECT_GT(r.render(level, *quality_preset("default")).stats.density_evals_per_pixel, 0.0);
}

TEST(LayersInView, FirstFrameThatSeesTheDeckAfterASkipHasNoHistory) {
  CloudRenderer& r = shared_renderer();
  r.set_weather(*weather::preset("overcast-stratus"));
  const RenderQuality q = *quality_preset("default");
  ViewRequest v = make_view(47.45, 8.56, 1500.0, 200.0, 25.0, "2026-06-21T11:30:00Z", 64, 36);
  v.reset_history = true;
  v.frame_index = 0;
  r.render(v, q);  // looking up: skipped
  v.reset_history = false;
  v.frame_index = 1;
  v.unix_time_s += 1.0 / 30.0;
  v.attitude.pitch_deg = -5.0;  // a pitch-down in one frame (30 deg: beyond the history's turn limit anyway)
  const FrameImage after = r.render(v, q);
  EXPECT_EQ(after.stats.marched_fraction, 1.0);  // every pixel marched: no history
  EXPECT_FALSE(after.stats.history_used);
  // the same frame from a renderer whose history was dropped (the same wind anchor: its
  // first render is the same look up at the same time)
  CloudRenderer fresh;
  fresh.set_weather(*weather::preset("overcast-stratus"));
  ViewRequest look_up = v;
  look_up.attitude.pitch_deg = 25.0;
  look_up.unix_time_s -= 1.0 / 30.0;
  look_up.reset_history = true;
  look_up.frame_index = 0;
  fresh.render(look_up, q);
  ViewRequest first = v;
  first.reset_history = true;
  const FrameImage ref = fresh.render(first, q);
  size_t differ = 0;
  for (size_t i = 0; i < after.rgba.size(); ++i) differ += after.rgba[i] != ref.rgba[i] ? 1 : 0;
  EXPECT_EQ(differ, 0u);
}

}  // namespace
}  // namespace cloudsvc::test
