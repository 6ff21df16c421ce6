// GL texture-sampling emulation of the reference (renderer/reference/texture_sampling.h)
// against values computed by hand from the OpenGL rules: texel centres at (i + 0.5) / n,
// GL_LINEAR weights, GL_REPEAT / GL_CLAMP_TO_EDGE index wrapping, R8 = byte / 255.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/reference/texture_sampling.h"

namespace cloudsvc::reference {
namespace {

constexpr double kPi = std::numbers::pi;

// 4^3 volume with texel (x, y, z) = 10 x + 50 y + 3 z (all < 256), x fastest.
weather::NoiseVolume ramp_volume() {
  weather::NoiseVolume v;
  v.size = 4;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) v.data.push_back(static_cast<std::uint8_t>(10 * x + 50 * y + 3 * z));
  return v;
}

double texel(int x, int y, int z) { return (10.0 * x + 50.0 * y + 3.0 * z) / 255.0; }

TEST(ReferenceSampling, TrilinearHitsTexelCentresExactly) {
  const weather::NoiseVolume v = ramp_volume();
  for (int x = 0; x < 4; ++x)
    for (int z = 0; z < 4; ++z)
      EXPECT_DOUBLE_EQ(sample_r8_trilinear_repeat(v, {(x + 0.5) / 4, (2 + 0.5) / 4, (z + 0.5) / 4}), texel(x, 2, z));
}

TEST(ReferenceSampling, TrilinearWeightsByHand) {
  const weather::NoiseVolume v = ramp_volume();
  // u = 0.3: x = 0.3 * 4 - 0.5 = 0.7 -> texels 0, 1 with weight 0.7 on texel 1;
  // v = 0.55: y = 1.7 -> texels 1, 2, weight 0.7; w = 0.9: z = 3.1 -> texels 3, 0 (repeat), 0.1.
  const double ax = 0.7, ay = 0.7, az = 0.1;
  double expected = 0.0;
  for (int dx = 0; dx < 2; ++dx)
    for (int dy = 0; dy < 2; ++dy)
      for (int dz = 0; dz < 2; ++dz) {
        const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay) * (dz ? az : 1 - az);
        expected += w * texel(dx, 1 + dy, dz ? 0 : 3);
      }
  EXPECT_NEAR(sample_r8_trilinear_repeat(v, {0.3, 0.55, 0.9}), expected, 1e-14);
}

TEST(ReferenceSampling, TrilinearRepeatsWithPeriodOne) {
  const weather::NoiseVolume v = ramp_volume();
  const glm::dvec3 p(0.123, 0.456, 0.789);
  const double a = sample_r8_trilinear_repeat(v, p);
  EXPECT_NEAR(sample_r8_trilinear_repeat(v, p + glm::dvec3(3.0, -7.0, 812.0)), a, 1e-12);
  EXPECT_NEAR(sample_r8_trilinear_repeat(v, p - glm::dvec3(1.0e6, 0.0, 0.0)), a, 1e-9);
  // Across the wrap: u = 0 lies halfway between texel 3 (centre 0.875 - 1) and texel 0.
  EXPECT_NEAR(sample_r8_trilinear_repeat(v, {0.0, 0.625, 0.125}), 0.5 * (texel(3, 2, 0) + texel(0, 2, 0)), 1e-14);
}

// 4 x 2 map: channel k of texel (i, j) = 100 j + 10 i + k.
weather::WeatherMap small_map() {
  weather::WeatherMap m;
  m.width = 4;
  m.height = 2;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) m.rgba.push_back(static_cast<float>(100 * j + 10 * i + k));
  return m;
}

TEST(ReferenceSampling, BilinearRepeatsInUAndClampsInV) {
  const weather::WeatherMap m = small_map();
  // Texel centre (i = 2, j = 1).
  EXPECT_DOUBLE_EQ(sample_rgba32f_bilinear_repeat_clamp(m, 2.5 / 4, 1.5 / 2).r, 120.0);
  // u = 0: halfway between texel 3 and texel 0 (repeat); v = 0: row 0 only (clamp).
  const glm::dvec4 w = sample_rgba32f_bilinear_repeat_clamp(m, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(w.r, 0.5 * (30.0 + 0.0));
  EXPECT_DOUBLE_EQ(w.a, 0.5 * (33.0 + 3.0));
  // v = 1: row 1 only.
  EXPECT_DOUBLE_EQ(sample_rgba32f_bilinear_repeat_clamp(m, 1.5 / 4, 1.0).g, 111.0);
  // v = 0.5: y = 0.5 -> rows 0 and 1 equally; u = 0.3: x = 0.7 -> texels 0, 1.
  EXPECT_NEAR(sample_rgba32f_bilinear_repeat_clamp(m, 0.3, 0.5).r, 0.5 * (7.0 + 107.0), 1e-12);
}

TEST(ReferenceSampling, PoleBlendReachesTheRowMeanAtThePole) {
  const weather::WeatherMap m = small_map();
  const glm::dvec4 south = weather_map_pole_value(m, false), north = weather_map_pole_value(m, true);
  EXPECT_DOUBLE_EQ(south.r, 15.0);   // mean of 0, 10, 20, 30
  EXPECT_DOUBLE_EQ(north.b, 117.0);  // mean of 102, 112, 122, 132
  // At the poles every longitude gives the pole value.
  for (double lon : {-3.0, -1.0, 0.0, 2.0})
    EXPECT_NEAR(sample_weather_map(m, south, north, -kPi / 2, lon).r, 15.0, 1e-12) << lon;
  EXPECT_NEAR(sample_weather_map(m, south, north, kPi / 2, 0.7).b, 117.0, 1e-12);
  // A quarter row from the south pole (y = -0.25): half way from the ring value to the pole.
  // lat = (v - 0.5) pi with v = 0.25 / 2 = 0.125; lon = -pi/2 -> u = 0.25 -> x = 0.5:
  // texels 0, 1 of row 0 (clamped), ring value (0 + 10) / 2 = 5; pole value 15.
  const double blended = sample_weather_map(m, south, north, (0.125 - 0.5) * kPi, -kPi / 2).r;
  EXPECT_NEAR(blended, 0.5 * (5.0 + 15.0), 1e-9);
  // Between the rows (no blend): latitude 0 -> y = 0.5.
  EXPECT_NEAR(sample_weather_map(m, south, north, 0.0, 0.0).r, 0.5 * (15.0 + 115.0), 1e-9);
}

TEST(ReferenceSampling, QuantilesFollowTheCountingDefinition) {
  // 300 texels: values 0..149 once, 200 x 150 times. #(x <= v) >= 300 i / 15 = 20 i.
  weather::NoiseVolume v;
  v.size = 0;  // only data is used
  for (int i = 0; i < 150; ++i) v.data.push_back(static_cast<std::uint8_t>(i));
  for (int i = 0; i < 150; ++i) v.data.push_back(200);
  const Quantiles16 q = value_quantiles(v);
  EXPECT_EQ(q[0], 0.0);
  EXPECT_EQ(q[15], 1.0);
  for (int i = 1; i <= 7; ++i) EXPECT_DOUBLE_EQ(q[static_cast<std::size_t>(i)], (20.0 * i - 1.0) / 255.0) << i;
  for (int i = 8; i <= 14; ++i) EXPECT_DOUBLE_EQ(q[static_cast<std::size_t>(i)], 200.0 / 255.0) << i;
  // Piecewise linear in between: p = 0.1 -> x = 1.5, halfway between q[1] and q[2].
  EXPECT_NEAR(interpolate_quantile(q, 0.1), 0.5 * (q[1] + q[2]), 1e-15);
  EXPECT_EQ(interpolate_quantile(q, -1.0), 0.0);
  EXPECT_EQ(interpolate_quantile(q, 2.0), 1.0);
}

}  // namespace
}  // namespace cloudsvc::reference
