// Procedural global weather map (weather/weather_map.h): determinism, range, no seam at the
// antimeridian, no pinching at the poles, channel statistics, sampling and coverage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "weather/weather_map.h"

namespace cloudsvc::weather {
namespace {

// One full-size map shared by the tests (generation takes ~0.2 s).
const WeatherMap& map7() {
  static const WeatherMap m = generate_procedural_map(7);
  return m;
}

float texel(const WeatherMap& m, int i, int j, int c) {
  return m.rgba[(static_cast<std::size_t>(j) * m.width + i) * 4 + c];
}

float sample_r(const WeatherMap& m, double lat, double lon) {
  float out[4];
  m.sample(lat, lon, out);
  return out[0];
}

TEST(WeatherMap, SizeAndRange) {
  const WeatherMap& m = map7();
  ASSERT_EQ(m.width, 1024);
  ASSERT_EQ(m.height, 512);
  ASSERT_EQ(m.rgba.size(), 1024u * 512u * 4u);
  for (std::size_t i = 0; i < m.rgba.size(); ++i) {
    ASSERT_TRUE(m.rgba[i] >= 0.0f && m.rgba[i] <= 1.0f) << i;
    if (i % 4 == 3) {
      ASSERT_EQ(m.rgba[i], 0.0f);
    }
  }
  EXPECT_TRUE(generate_procedural_map(1, 0, 0).rgba.empty());
}

TEST(WeatherMap, Deterministic) {
  const WeatherMap a = generate_procedural_map(11, 256, 128);
  const WeatherMap b = generate_procedural_map(11, 256, 128);
  EXPECT_EQ(a.rgba, b.rgba);
  const WeatherMap c = generate_procedural_map(12, 256, 128);
  double diff = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) diff += std::abs(a.rgba[i] - c.rgba[i]);
  EXPECT_GT(diff / a.rgba.size(), 0.05) << "different seeds must give different maps";
}

TEST(WeatherMap, ChannelStatistics) {
  for (std::uint32_t seed : {1u, 7u, 1234567u}) {
    const WeatherMap m = seed == 7 ? map7() : generate_procedural_map(seed, 512, 256);
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0, sum2 = 0.0;
      const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
      for (std::size_t i = 0; i < n; ++i) {
        sum += m.rgba[4 * i + c];
        sum2 += m.rgba[4 * i + c] * m.rgba[4 * i + c];
      }
      const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
      EXPECT_NEAR(mean, 0.5, 0.1) << "seed " << seed << " channel " << c;
      EXPECT_GT(sd, 0.12) << "seed " << seed << " channel " << c;
      EXPECT_LT(sd, 0.3) << "seed " << seed << " channel " << c;
    }
  }
}

// The columns either side of the antimeridian are as alike as any two neighbouring columns.
TEST(WeatherMap, NoSeamAtAntimeridianInTexels) {
  const WeatherMap& m = map7();
  double seam = 0.0, inside = 0.0;
  for (int j = 0; j < m.height; ++j) {
    seam += std::abs(texel(m, m.width - 1, j, 0) - texel(m, 0, j, 0));
    for (int i = 0; i + 1 < m.width; ++i) inside += std::abs(texel(m, i + 1, j, 0) - texel(m, i, j, 0));
  }
  seam /= m.height;
  inside /= static_cast<double>(m.height) * (m.width - 1);
  EXPECT_NEAR(seam / inside, 1.0, 0.3) << "seam " << seam << " inside " << inside;
}

TEST(WeatherMap, SamplingIsContinuousAcrossAntimeridian) {
  const WeatherMap& m = map7();
  for (double lat = -85.0; lat <= 85.0; lat += 5.0) {
    float a[4], b[4];
    m.sample(lat, 179.9999, a);
    m.sample(lat, -179.9999, b);
    // The points are 0.0002 deg apart (0.0006 texel): at most ~1e-3 apart for a map whose
    // neighbouring texels differ by up to ~1; a seam would be a jump of order 0.1.
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 1e-3) << "lat " << lat << " ch " << c;
    // Equivalent longitudes give the same value.
    m.sample(lat, 180.0, a);
    m.sample(lat, -180.0, b);
    EXPECT_EQ(a[0], b[0]);
    m.sample(lat, 10.0 + 720.0, a);
    m.sample(lat, 10.0, b);
    EXPECT_NEAR(a[0], b[0], 1e-6);
  }
  // Steps of 0.02 deg across the antimeridian are no larger than the largest such step
  // anywhere else along the same parallel.
  for (double lat : {-60.0, 0.0, 33.3, 71.0}) {
    const double step = 0.02;
    double max_elsewhere = 0.0;
    for (double lon = -179.0; lon < 179.0; lon += step) {
      max_elsewhere = std::max<double>(max_elsewhere,
                                       std::abs(sample_r(m, lat, lon + step) - sample_r(m, lat, lon)));
    }
    double max_across = 0.0;
    for (double lon = 179.5; lon < 180.5; lon += step) {
      max_across = std::max<double>(max_across,
                                    std::abs(sample_r(m, lat, lon + step) - sample_r(m, lat, lon)));
    }
    EXPECT_LE(max_across, max_elsewhere * 1.0001 + 1e-6) << "lat " << lat;
    EXPECT_GT(max_elsewhere, 0.0);
  }
}

TEST(WeatherMap, NoPinchingAtThePoles) {
  const WeatherMap& m = map7();
  const auto ring_spread = [&](double lat) {
    float lo = 1.0f, hi = 0.0f;
    for (int k = 0; k < 360; ++k) {
      const float v = sample_r(m, lat, -180.0 + k);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return hi - lo;
  };
  EXPECT_LT(ring_spread(89.99), 0.03);
  EXPECT_LT(ring_spread(-89.99), 0.03);
  EXPECT_LT(ring_spread(90.0), 1e-6);
  EXPECT_LT(ring_spread(-90.0), 1e-6);
  EXPECT_LT(ring_spread(95.0), 1e-6);  // clamped
  // Away from the pole the map does vary along a parallel (so the checks above can fail).
  EXPECT_GT(ring_spread(80.0), 0.1);
  // Continuous towards the pole: the last texel row blends into the pole value.
  const double last_row_lat = 90.0 - 90.0 / m.height;
  EXPECT_NEAR(sample_r(m, last_row_lat, 12.0), sample_r(m, last_row_lat - 1e-7, 12.0), 1e-4);
  EXPECT_NEAR(sample_r(m, last_row_lat, 12.0), sample_r(m, last_row_lat + 1e-7, 12.0), 1e-4);
}

TEST(WeatherMap, FeatureSizeFollowsParameter) {
  // Larger weather systems: smaller differences between neighbouring texels.
  const auto roughness = [](const WeatherMap& m) {
    double sum = 0.0;
    for (int j = m.height / 4; j < 3 * m.height / 4; ++j) {
      for (int i = 0; i + 1 < m.width; ++i) sum += std::abs(texel(m, i + 1, j, 0) - texel(m, i, j, 0));
    }
    return sum;
  };
  const double fine = roughness(generate_procedural_map(3, 256, 128, 300.0));
  const double coarse = roughness(generate_procedural_map(3, 256, 128, 3000.0));
  EXPECT_GT(fine, 3.0 * coarse);
}

TEST(WeatherMap, SampleHitsTexelCentresAndHandlesBadInput) {
  const WeatherMap& m = map7();
  const int i = 100, j = 300;
  const double lon = -180.0 + (i + 0.5) * 360.0 / m.width;
  const double lat = -90.0 + (j + 0.5) * 180.0 / m.height;
  float out[4];
  m.sample(lat, lon, out);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(out[c], texel(m, i, j, c), 1e-6);

  m.sample(std::nan(""), 0.0, out);
  EXPECT_EQ(out[0], 0.5f);
  m.sample(0.0, INFINITY, out);
  EXPECT_EQ(out[1], 0.5f);
  WeatherMap empty;
  empty.sample(0.0, 0.0, out);
  EXPECT_EQ(out[2], 0.5f);
  EXPECT_EQ(out[3], 0.0f);
}

TEST(LocalCoverage, Formula) {
  for (float m : {0.0f, 0.3f, 0.5f, 1.0f}) {
    EXPECT_EQ(local_coverage(0.0f, m), 0.0f);
    EXPECT_EQ(local_coverage(1.0f, m), 1.0f);
  }
  EXPECT_FLOAT_EQ(local_coverage(0.5f, 0.5f), 0.5f);
  EXPECT_FLOAT_EQ(local_coverage(0.3f, 0.75f), 0.3f + 1.2f * 0.3f * 0.5f);
  EXPECT_FLOAT_EQ(local_coverage(0.8f, 0.25f), 0.8f - 1.2f * 0.2f * 0.5f);
  EXPECT_EQ(local_coverage(0.5f, 1.0f), 1.0f);  // clamped
  EXPECT_EQ(local_coverage(0.5f, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(local_coverage(0.4f, std::nanf("")), 0.4f);
  EXPECT_EQ(local_coverage(std::nanf(""), 0.5f), 0.0f);
}

}  // namespace
}  // namespace cloudsvc::weather
