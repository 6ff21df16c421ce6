// Light bouncing between the ground and a cloud deck (issue: optics): under an overcast
// stratus deck, the ground's radiance and the deck's base radiance over snow (albedo 0.8)
// and over the sea (0.1), the light model (CPU reference: ground_cloud_gain in
// renderer/reference/cloud_lighting.h) against the path-traced truth, which follows every
// round trip between ground and cloud.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "renderer/reference/reference_renderer.h"
#include "renderer/truth/truth_renderer.h"
#include "tests/make_view.h"
#include "tests/sanitizer_build.h"
#include "weather/cloud_layer.h"

namespace cloudsvc {
namespace {

weather::Weather deck_over(double albedo) {
  weather::Weather w;
  w.map_seed = 11;
  weather::CloudLayer l;
  l.type = weather::CloudType::Stratus;
  l.base_m = 400.0;
  l.top_m = 900.0;
  l.coverage = 1.0;
  l.density_scale = weather::cloud_type_traits(l.type).default_density_scale;
  l.droplet_diameter_um = weather::cloud_type_traits(l.type).default_droplet_diameter_um;
  w.layers.push_back(l);
  w.ground_albedo = albedo;
  return w;
}

struct Pair {
  double model = 0.0, truth = 0.0, truth_se = 0.0;  // green, mean over the image
};

// 2 x 2 px over 10 deg from 100 m, straight down (the ground) or up (the deck's base),
// Zurich, 2026-06-21 10:00 UTC (sun 60 deg high).
Pair measure(double albedo, double pitch_deg) {
  const ViewRequest v = test::make_view(47.45, 8.56, 100.0, 0.0, pitch_deg, "2026-06-21T10:00:00Z", 2, 2, 10.0);
  const weather::Weather w = deck_over(albedo);
  const FrameImage ref = reference::render_reference(v, w, {});
  truth::TruthSettings ts;
  ts.spp = 2048;
  ts.seed = 3;
  ts.tracer.max_collisions = 200000;
  const truth::TruthImage t = truth::render_truth(v, w, ts);
  EXPECT_EQ(t.incomplete_pixels, 0);
  Pair p;
  double var = 0.0;
  for (int i = 0; i < 4; ++i) {
    p.model += ref.rgba[4 * i + 1] / 4.0;
    p.truth += t.image.rgba[4 * i + 1] / 4.0;
    var += t.image.std_error[3 * i + 1] * t.image.std_error[3 * i + 1] / 16.0;
  }
  p.truth_se = std::sqrt(var);
  return p;
}

TEST(GroundCloudBounce, SnowAndSeaUnderADeckFollowThePathTracer) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers
                                            << "; TruthTracer.GuidedCopiesFromSnow... traces the ground bounce here";
  const Pair ground_snow = measure(0.8, -90.0), ground_sea = measure(0.1, -90.0);
  const Pair base_snow = measure(0.8, 90.0), base_sea = measure(0.1, 90.0);
  const auto show = [](const char* what, const Pair& p) {
    std::printf("%-22s model %.4f  truth %.4f +- %.4f  (model / truth %.3f)\n", what, p.model, p.truth, p.truth_se,
                p.model / p.truth);
  };
  show("ground, snow", ground_snow);
  show("ground, sea", ground_sea);
  show("deck base, snow", base_snow);
  show("deck base, sea", base_sea);
  // What the round trips add: snow over sea. Without them the ground's ratio is the albedos'
  // (8); the truth's is over twice that.
  const double g_model = ground_snow.model / ground_sea.model, g_truth = ground_snow.truth / ground_sea.truth;
  const double b_model = base_snow.model / base_sea.model, b_truth = base_snow.truth / base_sea.truth;
  const double g_se = g_truth * std::hypot(ground_snow.truth_se / ground_snow.truth, ground_sea.truth_se / ground_sea.truth);
  const double b_se = b_truth * std::hypot(base_snow.truth_se / base_snow.truth, base_sea.truth_se / base_sea.truth);
  std::printf("snow / sea: ground model %.2f truth %.2f +- %.2f; deck base model %.3f truth %.3f +- %.3f\n", g_model,
              g_truth, g_se, b_model, b_truth, b_se);
  EXPECT_GT(g_truth, 12.0);
  EXPECT_NEAR(g_model, g_truth, 0.05 * g_truth + 2.0 * g_se);
  EXPECT_NEAR(b_model, b_truth, 0.05 * b_truth + 2.0 * b_se);
  // Absolute, each within 5 % plus twice the truth's standard error: the ground's light (the
  // deck's transmittance from the slab Monte Carlo table, model::slab_beam_transmittance /
  // slab_diffuse_transmittance) and the base's (the sun's, the sky's and the ground's light
  // from the Monte Carlo source tables, model::ms_source_table / ms_diffuse_incidence_table).
  for (const Pair* p : {&ground_snow, &ground_sea, &base_snow, &base_sea})
    EXPECT_NEAR(p->model, p->truth, 0.05 * p->truth + 2.0 * p->truth_se);
}

}  // namespace
}  // namespace cloudsvc
