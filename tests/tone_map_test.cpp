// Display tone mapping (common/tone_map.h), the one recipe of the service's PNG, RGBA8
// shared-memory and window frames and of sim_client's EXR conversion: non-finite and
// negative radiance never reaches a pixel as anything but black, and a known input gives
// the sRGB value the recipe predicts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "common/tone_map.h"

namespace cloudsvc {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Appends one RGBA pixel (push_back: GCC 12 warns falsely on insert of an initializer list).
void append(std::vector<float>& px, float r, float g, float b, float a) {
  px.push_back(r);
  px.push_back(g);
  px.push_back(b);
  px.push_back(a);
}

// width x 1 RGBA pixels of grey radiance `value` (W m^-2 sr^-1 nm^-1), alpha 1.
std::vector<float> grey(std::size_t width, float value) {
  std::vector<float> px;
  for (std::size_t i = 0; i < width; ++i) append(px, value, value, value, 1.0f);
  return px;
}

// A uniform grey of luminance L maps to key 0.18 (exposure 0.18 / L within [0.5, 5000]):
// ACES(0.18) = 0.18 (2.51 x 0.18 + 0.03) / (0.18 (2.43 x 0.18 + 0.59) + 0.14) = 0.26690;
// sRGB: 1.055 x 0.26690^(1 / 2.4) - 0.055 = 0.55346, x 255 = 141.13 -> 141.
TEST(ToneMap, MiddleGreyGivesTheRecipesSrgbValue) {
  for (float radiance : {0.05f, 1e-3f, 0.3f}) {
    SCOPED_TRACE(radiance);
    const std::vector<std::uint8_t> out = tone_map_srgb8(grey(16, radiance), 4);
    ASSERT_EQ(out.size(), 16u * 4u);
    for (std::size_t i = 0; i < 16; ++i) {
      EXPECT_EQ(out[i * 4 + 0], 141);
      EXPECT_EQ(out[i * 4 + 1], 141);
      EXPECT_EQ(out[i * 4 + 2], 141);
      EXPECT_EQ(out[i * 4 + 3], 255);
    }
  }
  // +1 EV: ACES(0.36) = 0.50364 -> sRGB 0.73775 x 255 = 188.13 -> 188.
  EXPECT_EQ(tone_map_srgb8(grey(4, 0.05f), 4, 1.0)[0], 188);
  // Black stays black; the exposure factor is clamped to at most 5000 (night stays dark).
  EXPECT_EQ(tone_map_srgb8(grey(4, 0.0f), 4)[0], 0);
  EXPECT_DOUBLE_EQ(tone_map_for(grey(4, 1e-9f), 4).exposure, 5000.0);
  EXPECT_DOUBLE_EQ(tone_map_for(grey(4, 5.0f), 4).exposure, 0.5);
}

TEST(ToneMap, SunDiskIsIgnoredByTheExposureAndSaturates) {
  std::vector<float> px = grey(16, 0.05f);
  px[0] = px[1] = px[2] = 100.0f;  // luminance >= 10: not part of the log average
  const std::vector<std::uint8_t> out = tone_map_srgb8(px, 4);
  EXPECT_EQ(out[0], 255);
  EXPECT_EQ(out[4], 141) << "the other pixels keep the exposure of the grey alone";
}

TEST(ToneMap, NonFiniteAndNegativeRadianceBecomeBlackAndLeaveTheExposureAlone) {
  const std::vector<float> bad = {kNaN, -kNaN, kInf, -kInf, -1.0f, -1e30f, -0.0f,
                                  std::numeric_limits<float>::denorm_min() * -1.0f};
  std::vector<float> px = grey(8, 0.05f);
  for (float v : bad) append(px, v, v, v, v);
  append(px, kNaN, 0.05f, kInf, 1.0f);  // bad channels beside a good one
  for (double ev : {0.0, -20.0, 20.0}) {
    SCOPED_TRACE(ev);
    const ToneMap t = tone_map_for(px, 4, ev);
    EXPECT_TRUE(std::isfinite(t.exposure));
    const std::vector<std::uint8_t> srgb = tone_map_srgb8(px, 4, ev);
    const std::vector<float> display = tone_map_display(px, 4, ev);
    ASSERT_EQ(display.size(), px.size());
    for (std::size_t i = 8; i < 8 + bad.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(srgb[i * 4 + c], 0) << "pixel " << i;
        EXPECT_EQ(display[i * 4 + c], 0.0f) << "pixel " << i;
      }
      EXPECT_EQ(srgb[i * 4 + 3], 255);
      EXPECT_EQ(display[i * 4 + 3], 1.0f);
    }
    const std::size_t mixed = 8 + bad.size();
    EXPECT_EQ(srgb[mixed * 4 + 0], 0);
    EXPECT_GT(display[mixed * 4 + 1], 0.0f) << "the finite channel of a pixel is kept";
    EXPECT_EQ(srgb[mixed * 4 + 2], 0);
    for (float v : display) {
      EXPECT_TRUE(std::isfinite(v));
      EXPECT_GE(v, 0.0f);
      EXPECT_LE(v, 1.0f);
    }
  }
  // Pixels whose luminance is not finite do not take part in the exposure; -0 and a
  // negative denormal count as black, as 0 does.
  std::vector<float> finite_only = grey(8, 0.05f);
  for (int i = 0; i < 2; ++i) append(finite_only, 0.0f, 0.0f, 0.0f, 0.0f);
  std::vector<float> with_nonfinite = finite_only;
  for (float v : {kNaN, kInf, -kInf}) append(with_nonfinite, v, v, v, v);
  EXPECT_DOUBLE_EQ(tone_map_for(with_nonfinite, 4).exposure, tone_map_for(finite_only, 4).exposure);
  // Nothing finite at all: the neutral key 1, exposure factor 0.5.
  EXPECT_DOUBLE_EQ(tone_map_for(std::vector<float>(16, kNaN), 4).exposure, 0.5);
}

// The two outputs are one recipe: the 8-bit values are the display values rounded; three
// channels without alpha give the same colours as four.
TEST(ToneMap, Srgb8IsTheRoundedDisplayValueForAnyChannelCount) {
  std::vector<float> rgba, rgb;
  for (int i = 0; i < 200; ++i) {
    const float r = 1e-4f * std::pow(1.08f, static_cast<float>(i)), g = 0.5f * r, b = 2.0f * r;
    append(rgba, r, g, b, 0.3f);
    rgb.push_back(r);
    rgb.push_back(g);
    rgb.push_back(b);
  }
  const std::vector<std::uint8_t> srgb = tone_map_srgb8(rgba, 4);
  EXPECT_EQ(tone_map_srgb8(rgb, 3), srgb);
  const std::vector<float> display = tone_map_display(rgba, 4);
  const std::vector<float> display3 = tone_map_display(rgb, 3);
  for (std::size_t i = 0; i < 200; ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(display[i * 4 + c], display3[i * 3 + c]);
      EXPECT_LE(std::abs(std::lround(display[i * 4 + c] * 255.0) - long{srgb[i * 4 + c]}), 1) << i;
    }
    EXPECT_EQ(display[i * 4 + 3], 1.0f);
  }
}

}  // namespace
}  // namespace cloudsvc
