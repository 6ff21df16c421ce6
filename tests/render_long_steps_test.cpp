// The march's long steps through empty air (shaders/cloud_march.comp,
// RenderQuality::long_step_factor) skip only what holds no cloud: a probe asks whether the
// span since the last sample can hold cloud anywhere (cloud_may_be_on_segment, a bound from
// the base noise's max pyramid and the height profile), so the image with long steps is the
// image without them, on views of every preset and on random scenes nobody chose (thin and
// far layers, grazing rays, inside a layer, poles, antimeridian), while the march does less
// work. Before the bound a probe sampled the base shape at its own point, and a cloud
// shorter than a probe step between two probes was lost (random scenes r2026-13, r2026-29:
// docs/ACCURACY.md, "Unseen scenes").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render_test_support.h"
#include "tests/fixtures/random_scenes.h"

namespace cloudsvc::test {
namespace {

// Largest |a - b| over rgb, relative to the brighter image's largest rgb value.
double worst_relative(const FrameImage& a, const FrameImage& b) {
  double peak = 1e-12, worst = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    peak = std::max({peak, static_cast<double>(a.rgba[i]), static_cast<double>(b.rgba[i])});
    worst = std::max(worst, std::abs(static_cast<double>(a.rgba[i]) - b.rgba[i]));
  }
  return worst / peak;
}

// One full frame (no temporal reuse), long steps x1 vs x4, everything else equal.
struct Pair {
  FrameImage fine, probed;
};
Pair render_pair(const weather::Weather& w, const ViewRequest& v) {
  RenderQuality fine;  // log steps, coverage pyramid, no reuse
  fine.long_step_factor = 1;
  RenderQuality probed = fine;
  probed.long_step_factor = 4;
  CloudRenderer& r = shared_renderer();
  r.set_weather(w);
  Pair p{r.render(v, fine), r.render(v, probed)};
  maybe_save(std::string("long_steps_") + w.name + "_fine", p.fine);
  maybe_save(std::string("long_steps_") + w.name + "_probed", p.probed);
  return p;
}

// The same image with and without long steps: every sample the full march takes with
// density > 0 is also taken by the probing march at the same distance (float round-off
// in the step-back arithmetic aside).
constexpr double kSameImage = 1e-5;

TEST(LongSteps, PresetViewsAreUnchangedAndCheaper) {
  struct View {
    const char* preset;
    double lat, lon, alt, heading, pitch;
  };
  const View views[] = {
      {"scattered-cumulus", 47.45, 8.56, 800.0, 250.0, 8.0},     // below, towards the horizon
      {"broken-cumulus", 47.45, 8.56, 6000.0, 30.0, -35.0},      // above, looking down
      {"cumulonimbus", 10.0, -60.0, 2000.0, 90.0, 2.0},          // towers at the horizon
      {"overcast-stratus", 60.0, 10.0, 3000.0, 180.0, -20.0},    // above the sheet
      {"stratocumulus-deck", -33.9, 151.2, 1200.0, 0.0, -5.0},   // inside the deck
  };
  double evals_fine = 0.0, evals_probed = 0.0;
  for (const View& s : views) {
    const ViewRequest v = make_view(s.lat, s.lon, s.alt, s.heading, s.pitch, "2026-06-21T10:30:00Z", 96, 54);
    const Pair p = render_pair(*weather::preset(s.preset), v);
    const double worst = worst_relative(p.fine, p.probed);
    std::printf("%-20s cloud px %lld / %lld, evals/px %.1f -> %.1f, worst relative difference %.1e\n", s.preset,
                static_cast<long long>(p.fine.stats.cloud_pixels), static_cast<long long>(p.probed.stats.cloud_pixels),
                p.fine.stats.density_evals_per_pixel, p.probed.stats.density_evals_per_pixel, worst);
    EXPECT_LE(worst, kSameImage) << s.preset;
    EXPECT_EQ(p.fine.stats.cloud_pixels, p.probed.stats.cloud_pixels) << s.preset;
    evals_fine += p.fine.stats.density_evals_per_pixel;
    evals_probed += p.probed.stats.density_evals_per_pixel;
  }
  EXPECT_LT(evals_probed, 0.9 * evals_fine);  // the probes do skip
}

TEST(LongSteps, RandomScenesAreUnchanged) {
  int scenes = 0;
  for (std::uint64_t seed : {2026u, 77u}) {
    for (const accuracy::RandomScene& s : accuracy::random_scenes(seed, 12)) {
      if (s.weather.layers.empty()) continue;
      const Pair p = render_pair(s.weather, accuracy::random_scene_view(s, 64, 36));
      const double worst = worst_relative(p.fine, p.probed);
      std::printf("%-8s cloud px %lld / %lld, evals/px %.1f -> %.1f, worst relative difference %.1e\n",
                  s.name.c_str(), static_cast<long long>(p.fine.stats.cloud_pixels),
                  static_cast<long long>(p.probed.stats.cloud_pixels), p.fine.stats.density_evals_per_pixel,
                  p.probed.stats.density_evals_per_pixel, worst);
      EXPECT_LE(worst, kSameImage) << s.name;
      EXPECT_EQ(p.fine.stats.cloud_pixels, p.probed.stats.cloud_pixels) << s.name;
      ++scenes;
    }
  }
  EXPECT_GE(scenes, 16);
}

}  // namespace
}  // namespace cloudsvc::test
