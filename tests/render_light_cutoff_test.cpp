// Light marches stop once the sun's beam is spent (RenderQuality::light_march_cutoff,
// shaders/cloud_march.comp): past an optical depth of 12 / w_D (27 for the smallest
// droplets) towards the sun the sun term, the peak beam e^(-w_D tau), is below 6e-6 of its
// unshadowed value whatever lies beyond, and earlier where the view's scattering angle
// bounds the peak beam below 1e-4 sr^-1 per unit horizontal solar flux
// (model::peak_beam_cutoff_tau), so the image may not change visibly (at most 0.3 % in
// any pixel: an 8-bit sRGB step is 0.4 % or more) while thick clouds need far fewer
// density evaluations. Cumulonimbus towers
// seen from beside them at 3 km (the thickest preset; from above, the thin anvil shield
// hides them and its light marches rarely reach tau 12) and a stratocumulus deck at sunset
// (long slant light paths), every pixel marched in full.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render_test_support.h"
#include "tests/fixtures/accuracy_scenes.h"

namespace cloudsvc::test {
namespace {

const std::vector<accuracy::AccuracyScene>& thick_scenes() {
  static const std::vector<accuracy::AccuracyScene> scenes = {
      accuracy::accuracy_scenes()[7],  // above stratocumulus at sunset
      {"beside cumulonimbus towers", "cumulonimbus", 3000.0, 135.0, 8.0, "2026-06-21T14:00:00Z", false},
  };
  return scenes;
}

class LightCutoff : public ::testing::TestWithParam<int> {};

TEST_P(LightCutoff, StopsSpentLightMarchesWithoutChangingTheImage) {
  const accuracy::AccuracyScene& s = thick_scenes()[static_cast<size_t>(GetParam())];
  const ViewRequest v = accuracy::accuracy_view(s, 96, 54);
  // the frame's cut-off applies to the peak beam's slowest decay, e^(-w_D tau) with the
  // smallest w_D of the droplet fit (model::peak_beam_slowest_decay: 0.448), i.e. at
  // tau = 12 / 0.448; the view's (peak_beam_cutoff_tau) comes first away from the sun
  RenderQuality every;
  every.light_march_cutoff = 0.0;
  RenderQuality cut = every;
  cut.light_march_cutoff = RenderQuality{}.light_march_cutoff;  // the default
  ASSERT_EQ(cut.light_march_cutoff, 12.0);
  // the second frame of each: the first also builds the ground shadow map (its own march)
  auto second_frame = [&](const RenderQuality& q) {
    render_preset(s.preset, v, q);
    return shared_renderer().render(v, q);
  };
  const FrameImage a = second_frame(every), b = second_frame(cut);
  ASSERT_GT(a.stats.cloud_pixels, 100);
  // difference per pixel relative to the pixel, with a floor of 1e-3 of the image's
  // brightest value (the sky behind thin cloud edges is dark in the blue at sunset)
  double peak = 0.0, worst = 0.0;
  for (float x : a.rgba) peak = std::max(peak, static_cast<double>(x));
  for (size_t k = 0; k < a.rgba.size(); ++k)
    worst = std::max(worst, std::abs(static_cast<double>(b.rgba[k]) - a.rgba[k]) / (std::abs(a.rgba[k]) + 1e-3 * peak));
  std::printf("%s: density evaluations per pixel %.1f -> %.1f, worst relative change %.2e\n", s.name,
              a.stats.density_evals_per_pixel, b.stats.density_evals_per_pixel, worst);
  EXPECT_LT(worst, 3e-3);
  EXPECT_LT(b.stats.density_evals_per_pixel, 0.9 * a.stats.density_evals_per_pixel);
}

std::string scene_name(const ::testing::TestParamInfo<int>& info) {
  std::string n = thick_scenes()[static_cast<size_t>(info.param)].name;
  for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(ThickClouds, LightCutoff, ::testing::Values(0, 1), scene_name);

}  // namespace
}  // namespace cloudsvc::test
