// A view's near and far planes (ViewRequest::near_m, far_m; CIGI View Definition): clouds
// beyond the far plane or before the near plane are not drawn, the sky and the ground are.
// Broken cumulus seen from 3000 m looking 20 deg down (64x36, the default preset held still
// for 17 frames): a far plane at 6 km leaves fewer cloud pixels than none, in the GPU and
// the CPU reference alike (cloud pixels within 3 points of each other); a near plane beyond
// every cloud leaves none, in both, and the two images agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render_test_support.h"
#include "renderer/quality_presets.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/reference_renderer.h"

namespace cloudsvc::test {
namespace {

double mean_abs_rgb_difference(const FrameImage& a, const FrameImage& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    if (i % 4 != 3) d += std::abs(a.rgba[i] - b.rgba[i]);
  return d / static_cast<double>(a.rgba.size() / 4 * 3);
}

double mean_rgb(const FrameImage& a) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    if (i % 4 != 3) s += a.rgba[i];
  return s / static_cast<double>(a.rgba.size() / 4 * 3);
}

TEST(ClipPlanes, CloudsOutsideTheNearAndFarPlanesAreNotDrawn) {
  CloudRenderer& gpu = shared_renderer();
  const RenderQuality q = *quality_preset("default");
  const weather::Weather w = *weather::preset("broken-cumulus");
  gpu.set_weather(w);
  ViewRequest v = make_view(47.4, 8.5, 3000.0, 90.0, -20.0, "2026-06-21T10:00:00Z", 64, 36);

  const FrameImage whole = render_still_view(gpu, v, q);
  const FrameImage whole_ref = reference::render_reference(v, w, {});
  v.far_m = 6000.0;
  const FrameImage far = render_still_view(gpu, v, q);
  const FrameImage far_ref = reference::render_reference(v, w, {});
  maybe_save("clip_far_6km", far);
  const double c_whole = reference::cloud_fraction(reference::opacity_field(whole));
  const double c_whole_ref = reference::cloud_fraction(reference::opacity_field(whole_ref));
  const double c_far = reference::cloud_fraction(reference::opacity_field(far));
  const double c_far_ref = reference::cloud_fraction(reference::opacity_field(far_ref));
  std::printf("cloud pixels, no plane: GPU %.1f %%, reference %.1f %%; far plane 6 km: GPU %.1f %%, reference %.1f %%\n",
              100.0 * c_whole, 100.0 * c_whole_ref, 100.0 * c_far, 100.0 * c_far_ref);
  EXPECT_GT(c_whole_ref, 0.2);
  EXPECT_LT(c_far_ref, 0.8 * c_whole_ref) << "the far plane removes the distant clouds";
  EXPECT_GT(c_far_ref, 0.01) << "and keeps the near ones";
  EXPECT_NEAR(c_far, c_far_ref, 0.03);
  EXPECT_NEAR(c_whole, c_whole_ref, 0.03);
  EXPECT_EQ(far.stats.nonfinite_pixels, 0);

  // A near plane beyond every cloud the view reaches: no cloud is drawn, while their
  // shadows stay on the ground; the GPU and the reference agree on the image.
  v.far_m = 0.0;
  v.near_m = 1.0e6;
  const FrameImage none = render_still_view(gpu, v, q);
  const FrameImage none_ref = reference::render_reference(v, w, {});
  const double diff = mean_abs_rgb_difference(none, none_ref) / mean_rgb(none_ref);
  std::printf("near plane at 1000 km: cloud pixels GPU %.1f %%, reference %.1f %%; mean |GPU - reference| %.4f of "
              "the mean radiance\n",
              100.0 * reference::cloud_fraction(reference::opacity_field(none)),
              100.0 * reference::cloud_fraction(reference::opacity_field(none_ref)), diff);
  EXPECT_EQ(reference::cloud_fraction(reference::opacity_field(none)), 0.0);
  EXPECT_EQ(reference::cloud_fraction(reference::opacity_field(none_ref)), 0.0);
  EXPECT_LT(diff, 0.05);
}

}  // namespace
}  // namespace cloudsvc::test
