// Forecast weather in the GPU renderer (weather/forecast_frame.h, CloudRenderer::set_forecast):
// each layer's local coverage comes from its own channel of the weather map's layer
// coverage, so two layers can have clouds in different places, as a forecast's low and high
// cloud do. A forecast with overcast low cloud east of 8 E and overcast high cloud west of
// it, seen from 5 km between them: looking down, the deck only in the east; looking up,
// the high cloud only in the west. A uniform weather with the same layers would show both
// everywhere.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forecast_test_support.h"
#include "render_test_support.h"
#include "weather/forecast_frame.h"

namespace cloudsvc::test {
namespace {

// Overcast low cloud east of 8° E, overcast high cloud west of it.
const FunctionForecast split_forecast("split", [](double, double lon_deg) {
  weather::CloudColumn c;
  const bool east = lon_deg > 8.0;
  c[weather::CloudBand::Low] = {east ? 1.0 : 0.0, 1000.0, 1600.0};
  c[weather::CloudBand::Middle] = {0.0};
  c[weather::CloudBand::High] = {east ? 0.0 : 1.0, 8000.0, 9500.0};
  c[weather::CloudBand::Convective] = {0.0};
  return c;
});

double cloud_fraction(const FrameImage& img) {
  return static_cast<double>(img.stats.cloud_pixels) / (static_cast<double>(img.width) * img.height);
}

TEST(ForecastWeather, EachLayerHasCloudWhereItsOwnChannelPutsIt) {
  CloudRenderer& r = shared_renderer();
  const auto& forecast = split_forecast;
  const char* time = "2026-06-21T10:00:00Z";
  struct Case {
    double lon, pitch;
    bool cloudy;
    const char* what;
  };
  for (const Case& c : {Case{9.5, -90.0, true, "east, down: the low deck"}, Case{9.5, 90.0, false, "east, up: no high cloud"},
                        Case{6.5, -90.0, false, "west, down: no low deck"}, Case{6.5, 90.0, true, "west, up: the high cloud"}}) {
    const ViewRequest v = make_view(47.0, c.lon, 5000.0, 0.0, c.pitch, time, 96, 54);
    const weather::Weather w = weather::forecast_weather_at(forecast, 47.0, c.lon, v.unix_time_s);
    ASSERT_EQ(w.layers.size(), 2u) << c.what;  // both slots are in the region
    EXPECT_EQ(w.layers[0].coverage_channel, weather::kLowSlot);
    EXPECT_EQ(w.layers[1].coverage_channel, weather::kHighSlot);
    r.set_forecast(w, weather::forecast_map(forecast, v.unix_time_s, r.weather_map_width(), r.weather_map_height()));
    const FrameImage img = r.render(v);
    maybe_save(std::string("forecast_") + (c.lon > 8 ? "east_" : "west_") + (c.pitch < 0 ? "down" : "up"), img);
    const double f = cloud_fraction(img);
    std::printf("%s: cloud pixels %.1f %%\n", c.what, 100.0 * f);
    EXPECT_EQ(img.stats.nonfinite_pixels, 0);
    if (c.cloudy) EXPECT_GT(f, 0.95) << c.what;
    else EXPECT_LT(f, 0.02) << c.what;
  }
  // The same layers with their own coverage (channel -1) put cloud everywhere.
  weather::Weather uniform = weather::forecast_weather_at(forecast, 47.0, 9.5, 0.0);
  for (weather::CloudLayer& l : uniform.layers) {
    l.coverage_channel = -1;
    l.coverage = 1.0;
  }
  r.set_weather(uniform);
  EXPECT_GT(cloud_fraction(r.render(make_view(47.0, 9.5, 5000.0, 0.0, 90.0, time, 96, 54))), 0.95);
}

TEST(ForecastWeather, AForecastMapOfAnotherSizeIsRejected) {
  CloudRenderer& r = shared_renderer();
  const auto& forecast = split_forecast;
  const weather::Weather w = weather::forecast_weather_at(forecast, 47.0, 9.5, 0.0);
  EXPECT_THROW(r.set_forecast(w, weather::forecast_map(forecast, 0.0, 64, 32)), std::invalid_argument);
  weather::WeatherMap no_channels = weather::forecast_map(forecast, 0.0, r.weather_map_width(), r.weather_map_height());
  no_channels.layer_coverage.clear();
  EXPECT_THROW(r.set_forecast(w, no_channels), std::invalid_argument);
}

}  // namespace
}  // namespace cloudsvc::test
