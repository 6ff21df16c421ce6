// A service's weather changing under a moving view (CloudRenderer::update_weather,
// update_forecast): the same weather sent again changes nothing (hosts resend theirs every
// frame), and a change that keeps every layer's wind lets the clouds drift on from where they
// are instead of jumping back to where the wind anchor restarts them; set_weather and a
// changed wind restart the drift, as before.
#include <gtest/gtest.h>

#include "renderer/quality_presets.h"
#include "render_test_support.h"
#include "weather/presets.h"

namespace cloudsvc::test {
namespace {

constexpr double kT0 = 1782043200.0;  // 2026-06-21 12:00 UTC

// Frame k of a 30 Hz sequence from kT0.
double frame_time(int k) { return kT0 + k / 30.0; }

ViewRequest view_at(int k) {
  const double t = frame_time(k);
  ViewRequest v;
  v.position = {47.0, 8.0, 2500.0};
  v.attitude = {90.0, 5.0, 0.0};
  v.fov_deg = 50.0;
  v.width = 48;
  v.height = 27;
  v.unix_time_s = t;
  v.frame_index = static_cast<std::uint32_t>(k);
  return v;
}

TEST(WeatherUpdate, ResentWeatherKeepsTheHistoryAndAChangeWithTheSameWindsKeepsTheDrift) {
  CloudRenderer& r = shared_renderer();
  const RenderQuality q = *quality_preset("default");  // temporal reuse
  weather::Weather w = *weather::preset("broken-cumulus");
  ASSERT_NE(w.layers.at(0).wind.east_mps, 0.0) << "the preset drifts: the test checks the drift";
  r.set_weather(w);
  ViewRequest v = view_at(0);
  v.reset_history = true;
  EXPECT_EQ(count_bad_values(r.render(v, q)), 0);
  ASSERT_TRUE(r.wind_anchor());
  const WindAnchor anchor = *r.wind_anchor();
  EXPECT_EQ(anchor.unix_time_s, frame_time(0));
  EXPECT_TRUE(r.render(view_at(1), q).stats.history_used);

  // the same weather again: nothing changes
  r.update_weather(w);
  EXPECT_TRUE(r.render(view_at(2), q).stats.history_used) << "resent weather kept the history";
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(0));

  // a visibility and a coverage change with the same winds: new clouds to march, same drift
  w.visibility_m = 20000.0;
  w.layers[0].coverage = 0.4;
  r.update_weather(w);
  EXPECT_EQ(r.weather(), w);
  const FrameImage changed = r.render(view_at(3), q);
  EXPECT_FALSE(changed.stats.history_used) << "other clouds: nothing to reuse";
  EXPECT_EQ(count_bad_values(changed), 0);
  ASSERT_TRUE(r.wind_anchor());
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(0)) << "the clouds drift on from where they were";
  EXPECT_EQ(r.wind_anchor()->position.lat_deg, anchor.position.lat_deg);

  // a wind that changes restarts the drift from the next view
  w.layers[0].wind.east_mps += 5.0;
  r.update_weather(w);
  r.render(view_at(4));
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(4));

  // set_weather restarts it whatever changed (a new scene)
  r.render(view_at(5));
  r.set_weather(w);
  r.render(view_at(6));
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(6));
}

TEST(WeatherUpdate, AForecastsNewMapsKeepTheDriftWhereTheWindsStay) {
  CloudRenderer& r = shared_renderer();
  weather::Weather w = single_layer(weather::CloudType::Stratocumulus, 1200.0, 1800.0, 0.6);
  w.layers[0].wind = {8.0, -3.0};
  w.layers[0].coverage_channel = 0;
  weather::WeatherMap map;
  map.width = r.weather_map_width();
  map.height = r.weather_map_height();
  const std::size_t texels = static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height);
  map.rgba.assign(texels * 4, 0.5f);
  map.layer_coverage.assign(texels * 4, 0.6f);
  r.set_forecast(w, map);
  r.render(view_at(10));
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(10));
  map.layer_coverage.assign(texels * 4, 0.3f);
  r.update_forecast(w, map);  // the host's layer thinned: same winds
  EXPECT_EQ(count_bad_values(r.render(view_at(11))), 0);
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(10));
  w.layers[0].coverage = 0.3;
  r.update_forecast_layers(w);
  r.render(view_at(12));
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(10));
  w.layers[0].wind = {-4.0, 0.0};
  r.update_forecast(w, map);
  r.render(view_at(13));
  EXPECT_EQ(r.wind_anchor()->unix_time_s, frame_time(13)) << "a new wind restarts the drift";
  r.set_weather(*weather::preset("broken-cumulus"));  // leave the shared renderer as others expect
}

}  // namespace
}  // namespace cloudsvc::test
