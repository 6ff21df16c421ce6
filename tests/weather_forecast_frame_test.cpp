// Forecast weather -> the renderer's layers and layer-coverage map (weather/forecast_frame.h),
// and the weather map's layer-coverage channels (weather_map.h): sampling, poles, bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "forecast_test_support.h"
#include "weather/forecast_frame.h"

namespace {

using namespace cloudsvc::weather;

// Low cloud whose cover rises eastwards (0 at 0 E to 1 at 20 E), a fixed middle deck, and
// shallow convection north of 50 N.
const cloudsvc::test::FunctionForecast ramp_forecast("ramp", [](double lat, double lon) {
  CloudColumn c;
  c[CloudBand::Low] = {std::clamp(lon / 20.0, 0.0, 1.0), 1000.0, 1800.0};
  c[CloudBand::Middle] = {0.3, 3500.0, 4500.0};
  c[CloudBand::High] = {0.0};
  c[CloudBand::Convective] = {lat > 50.0 ? 0.9 : 0.0, 1200.0, 3000.0};
  return c;
});

TEST(ForecastFrame, LayersOfTheRegionReadTheirSlotsChannels) {
  const auto& f = ramp_forecast;
  const Weather w = forecast_weather_at(f, 45.0, 10.0, 0.0);
  EXPECT_EQ(validate(w), "");
  ASSERT_EQ(w.layers.size(), 2u);
  EXPECT_EQ(w.layers[0].type, CloudType::Stratocumulus);
  EXPECT_EQ(w.layers[0].coverage_channel, kLowSlot);
  EXPECT_NEAR(w.layers[0].coverage, 0.5, 0.01);  // the region's mean: the ramp is linear across it
  EXPECT_DOUBLE_EQ(w.layers[0].base_m, 1000.0);
  EXPECT_EQ(w.layers[1].type, CloudType::Altocumulus);
  EXPECT_EQ(w.layers[1].coverage_channel, kMiddleSlot);
  // North of 50 N the low cloud is cumulus (shallow convection makes up more than half of it).
  EXPECT_EQ(forecast_weather_at(f, 60.0, 10.0, 0.0).layers[0].type, CloudType::Cumulus);
}

TEST(ForecastFrame, TheMapHoldsEverySlotsCoverAtItsTexels) {
  const auto& f = ramp_forecast;
  const WeatherMap m = forecast_map(f, 0.0, 360, 180);
  ASSERT_TRUE(m.has_layer_coverage());
  float c[4], w[4];
  m.sample_layer_coverage(30.0, 10.0, c);
  EXPECT_NEAR(c[kLowSlot], 0.5, 1e-5);
  EXPECT_NEAR(c[kMiddleSlot], 0.3, 1e-6);
  EXPECT_NEAR(c[kHighSlot], 0.0, 1e-6);
  EXPECT_NEAR(c[kDeepConvectionSlot], 0.0, 1e-6);
  m.sample_layer_coverage(60.0, 10.0, c);
  EXPECT_NEAR(c[kLowSlot], 0.9, 1e-5);  // the convective cloud widens the low cloud
  m.sample(30.0, 10.0, w);               // R, G, B neutral: nothing modulates the layers
  EXPECT_FLOAT_EQ(w[0], 0.5f);
  EXPECT_FLOAT_EQ(w[1], 0.5f);
  // One value at each pole, whatever the longitude.
  float p[4];
  m.layer_coverage_pole_value(true, p);
  for (double lon : {-170.0, 5.0, 99.0}) {
    m.sample_layer_coverage(90.0, lon, c);
    EXPECT_FLOAT_EQ(c[kLowSlot], p[kLowSlot]);
  }
  // The bound for culling covers R and every channel.
  const std::size_t texel = static_cast<std::size_t>(120) * 360 + 190;  // 30.5 N, 10.5 E
  EXPECT_FLOAT_EQ(m.coverage_bound(texel), std::max({0.5f, m.layer_coverage[4 * texel], m.layer_coverage[4 * texel + 1]}));
  m.sample_layer_coverage(30.0, 19.5, c);
  EXPECT_GE(m.coverage_bound(texel + 9), c[kLowSlot] - 0.03f);
}

TEST(ForecastFrame, LayerLocalCoverageTakesAChannelAsItIs) {
  EXPECT_FLOAT_EQ(layer_local_coverage(0, 0.2f, 0.7f), 0.7f);
  EXPECT_FLOAT_EQ(layer_local_coverage(2, 0.9f, 1.5f), 1.0f);
  EXPECT_FLOAT_EQ(layer_local_coverage(1, 0.9f, std::nanf("")), 0.0f);
  EXPECT_FLOAT_EQ(layer_local_coverage(-1, 0.3f, 0.75f), local_coverage(0.3f, 0.75f));
  Weather w;
  w.layers.push_back(default_layer(CloudType::Stratus));
  w.layers[0].coverage_channel = 4;
  EXPECT_EQ(validate(w), "layers[0].coverage_channel 4 out of range [-1, 3]");
}

}  // namespace
