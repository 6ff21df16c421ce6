// What `sim_client cigi` sends an IG (sim_client/cigi_host_frames.h), read back with the IG's
// own reader and state (protocol/cigi/cigi_datagram.h, cigi_ig_state.h, cigi_weather.h) in
// both byte orders: the IG must see the pose, the side-by-side views, the sky's date and time
// and the cloud layers (with their wind the right way round) that the flight log and weather
// gave, or the replayed images do not show what the user asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "protocol/cigi/cigi_datagram.h"
#include "protocol/cigi/cigi_ig_state.h"
#include "protocol/cigi/cigi_weather.h"
#include "sim_client/cigi_host_frames.h"
#include "weather/presets.h"

namespace cloudsvc::sim {
namespace {

constexpr cigi::ByteOrder kOrders[] = {cigi::ByteOrder::Big, cigi::ByteOrder::Little};
constexpr double kPi = 3.14159265358979323846;

double utc(int y, int mo, int d, int h, int mi, int s) {
  const std::optional<double> t = geo::utc_from_civil(y, mo, d, h, mi, s);
  EXPECT_TRUE(t);
  return t.value_or(0.0);
}

protocol::Pose pose_at(double utc_unix_s) {
  protocol::Pose p;
  p.sim_time_s = 12.5;
  p.utc_unix_s = utc_unix_s;
  p.lat_deg = 47.458333333333336;
  p.lon_deg = -122.3088888888889;
  p.alt_m = 2134.567;
  p.heading_deg = 271.123456;
  p.pitch_deg = 3.3333;
  p.roll_deg = -12.987654;
  return p;
}

// The IG's reading of a host datagram: usable, nothing rejected.
cigi::HostDatagram read(const std::vector<std::uint8_t>& bytes, cigi::ByteOrder order) {
  cigi::HostDatagram d = cigi::read_host_datagram(bytes);
  EXPECT_TRUE(d.usable);
  EXPECT_TRUE(d.rejections.empty()) << d.rejections.front().reason;
  EXPECT_EQ(d.order, order);
  return d;
}

// The IG's state after the datagrams of `frames`, in order.
cigi::IgState apply(const std::vector<HostFrame>& frames, cigi::ByteOrder order) {
  cigi::IgState s;
  for (const HostFrame& f : frames) {
    const std::vector<std::string> refused = s.apply(read(host_datagram(f, order), order));
    EXPECT_TRUE(refused.empty()) << refused.front();
  }
  return s;
}

weather::Weather three_layers() {
  weather::Weather w;
  w.name = "three";
  weather::CloudLayer st = weather::default_layer(weather::CloudType::Stratus);
  st.base_m = 300.0;
  st.top_m = 650.0;
  st.coverage = 1.0;
  st.wind = {0.0, 0.0};  // calm
  weather::CloudLayer sc = weather::default_layer(weather::CloudType::Stratocumulus);
  sc.base_m = 1500.25;
  sc.top_m = 2100.0;
  sc.coverage = 0.37;
  sc.wind = {0.0, -6.5};  // towards the south: blows from the north
  weather::CloudLayer ci = weather::default_layer(weather::CloudType::Cirrus);
  ci.base_m = 8500.0;
  ci.top_m = 9700.0;
  ci.coverage = 0.15;
  ci.wind = {-41.0, 12.5};  // towards the west-north-west
  ci.density_scale *= 2.5;   // more ice than the type's typical
  w.layers = {st, sc, ci};
  return w;
}

TEST(SimClientCigiHostFrames, TheIgSeesThePoseTheFrameCountersAndTheTimestamp) {
  const double t = utc(2026, 6, 21, 10, 17, 42);
  for (cigi::ByteOrder order : kOrders) {
    HostFrame f;
    f.host_frame = 4711;
    f.last_ig_frame = 4709;
    f.pose = pose_at(t + 0.75);
    const cigi::HostDatagram d = read(host_datagram(f, order), order);
    EXPECT_EQ(d.ig_control.host_frame, 4711u);
    EXPECT_EQ(d.ig_control.last_ig_frame, 4709u);
    EXPECT_EQ(d.ig_control.mode, cigi::IgMode::Operate);
    EXPECT_TRUE(d.ig_control.timestamp_valid);
    EXPECT_EQ(d.ig_control.timestamp, 1250000u) << "sim time 12.5 s in ticks of 10 us";

    cigi::IgState s;
    EXPECT_TRUE(s.apply(d).empty());
    EXPECT_EQ(s.last_host_frame(), 4711u);
    ASSERT_TRUE(s.ownship());
    const cigi::OwnshipPose& o = *s.ownship();
    EXPECT_EQ(o.lat_deg, f.pose.lat_deg);
    EXPECT_EQ(o.lon_deg, f.pose.lon_deg);
    EXPECT_EQ(o.alt_m, f.pose.alt_m);
    EXPECT_NEAR(o.yaw_deg, f.pose.heading_deg, 1e-4);
    EXPECT_NEAR(o.pitch_deg, f.pose.pitch_deg, 1e-5);
    EXPECT_NEAR(o.roll_deg, f.pose.roll_deg, 1e-5);
    EXPECT_EQ(s.utc_s(), utc(2026, 6, 21, 10, 17, 0)) << "the sky's time: to the minute";
    EXPECT_EQ(s.views().size(), 1u) << "no views in this frame: the IG's default view";
    EXPECT_FALSE(s.global_layers()[0]) << "no weather in this frame";
  }
}

TEST(SimClientCigiHostFrames, TheIgGetsTheSideBySideViews) {
  const std::vector<cigi::ViewDefinition> views = side_by_side_views(3, 60.0, 9.0 / 16.0);
  const double half_v = std::atan(std::tan(30.0 * kPi / 180.0) * 9.0 / 16.0) * 180.0 / kPi;
  for (cigi::ByteOrder order : kOrders) {
    HostFrame f;
    f.host_frame = 1;
    f.pose = pose_at(utc(2026, 6, 21, 10, 17, 42));
    f.views = &views;
    f.view_count = 3;
    f.view_hfov_deg = 60.0;
    const cigi::IgState s = apply({f}, order);
    const std::vector<cigi::View> got = s.views();
    ASSERT_EQ(got.size(), 3u);
    const float yaws[] = {-60.0f, 0.0f, 60.0f};
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(got[i].id, i);
      EXPECT_EQ(got[i].yaw_deg, yaws[i]) << i;
      EXPECT_EQ(got[i].pitch_deg, 0.0f) << i;
      EXPECT_EQ(got[i].roll_deg, 0.0f) << i;
      EXPECT_FLOAT_EQ(got[i].frustum.left_deg, -30.0f) << i;
      EXPECT_FLOAT_EQ(got[i].frustum.right_deg, 30.0f) << i;
      EXPECT_NEAR(got[i].frustum.top_deg, half_v, 1e-5) << i;
      EXPECT_NEAR(got[i].frustum.bottom_deg, -half_v, 1e-5) << i;
    }
    // The views are still there in the frames that do not repeat them.
    HostFrame next = f;
    next.host_frame = 2;
    next.views = nullptr;
    const cigi::IgState s2 = apply({f, next}, order);
    EXPECT_EQ(s2.views(), got);
  }
  // Two views: the pair straddles the nose.
  const std::vector<cigi::ViewDefinition> two = side_by_side_views(2, 50.0, 0.75);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(side_by_side_control(two[0], 2, 50.0).yaw_deg, -25.0f);
  EXPECT_EQ(side_by_side_control(two[1], 2, 50.0).yaw_deg, 25.0f);
}

TEST(SimClientCigiHostFrames, TheSkysTimeIsThePosesUtcToTheMinute) {
  struct Case {
    int y, mo, d, h, mi, s;
    double frac;
  };
  const Case cases[] = {
      {2026, 6, 21, 10, 17, 42, 0.0},
      {1999, 12, 31, 23, 59, 59, 0.0},
      {1999, 12, 31, 23, 59, 59, 0.999},  // not rounded up into the next year
      {2024, 2, 29, 0, 0, 30, 0.5},       // leap day
      {2000, 1, 1, 0, 0, 0, 0.0},
  };
  for (cigi::ByteOrder order : kOrders)
    for (const Case& c : cases) {
      HostFrame f;
      f.host_frame = 1;
      f.pose = pose_at(utc(c.y, c.mo, c.d, c.h, c.mi, c.s) + c.frac);
      const cigi::IgState s = apply({f}, order);
      ASSERT_TRUE(s.utc_s()) << c.y << "-" << c.mo << "-" << c.d;
      EXPECT_EQ(*s.utc_s(), utc(c.y, c.mo, c.d, c.h, c.mi, 0))
          << geo::format_utc_iso8601(*f.pose.utc_unix_s) << " -> " << geo::format_utc_iso8601(*s.utc_s());
    }
}

TEST(SimClientCigiHostFrames, CelestialControlCarriesDateAndTimeToTheMinute) {
  cigi::CelestialSphereControl c = celestial_control(utc(2026, 6, 21, 10, 17, 42) + 0.9);
  EXPECT_TRUE(c.date_valid);
  EXPECT_EQ(c.hour, 10);
  EXPECT_EQ(c.minute, 17);
  EXPECT_EQ(c.date, 6212026u);

  c = celestial_control(utc(1999, 12, 31, 23, 59, 59) + 0.5);
  EXPECT_EQ(c.hour, 23);
  EXPECT_EQ(c.minute, 59);
  EXPECT_EQ(c.date, 12311999u);

  c = celestial_control(utc(2000, 1, 1, 0, 0, 0));
  EXPECT_EQ(c.hour, 0);
  EXPECT_EQ(c.minute, 0);
  EXPECT_EQ(c.date, 1012000u);

  c = celestial_control(utc(2024, 2, 29, 13, 5, 0));
  EXPECT_EQ(c.hour, 13);
  EXPECT_EQ(c.minute, 5);
  EXPECT_EQ(c.date, 2292024u);
}

// The layers as the IG's state and the renderer's weather built from it see them.
void expect_weather_round_trip(const weather::Weather& w, cigi::ByteOrder order) {
  SCOPED_TRACE(w.name);
  HostFrame f;
  f.host_frame = 1;
  f.pose = pose_at(utc(2026, 6, 21, 10, 17, 42));
  f.weather = &w;
  const cigi::IgState s = apply({f}, order);

  const cigi::CloudLayerSet& layers = s.global_layers();
  for (std::size_t i = 0; i < 3; ++i) {
    if (i >= w.layers.size()) {
      EXPECT_FALSE(layers[i]) << "slot " << i << ": no such layer, disabled";
      continue;
    }
    const weather::CloudLayer& l = w.layers[i];
    ASSERT_TRUE(layers[i]) << "slot " << i;
    const cigi::WeatherControl& c = *layers[i];
    EXPECT_EQ(c.layer_id, i + 1);
    EXPECT_EQ(c.scope, cigi::WeatherScope::Global);
    EXPECT_EQ(c.cloud_type, static_cast<int>(l.type)) << i;
    EXPECT_FLOAT_EQ(c.base_elevation_m, static_cast<float>(l.base_m)) << i;
    EXPECT_FLOAT_EQ(c.thickness_m, static_cast<float>(l.top_m - l.base_m)) << i;
    EXPECT_FLOAT_EQ(c.coverage_pct, static_cast<float>(100.0 * l.coverage)) << i;
  }

  // The renderer's weather: the same layers, altitudes and winds (CIGI sends where the wind
  // blows from; the renderer's wind points where the air goes).
  const cigi::CigiWeather cw = cigi::cigi_weather(s, f.pose.lat_deg, f.pose.lon_deg, 64, 32);
  EXPECT_TRUE(cw.notes.empty()) << cw.notes.front();
  ASSERT_EQ(cw.weather.layers.size(), w.layers.size());
  for (std::size_t i = 0; i < w.layers.size(); ++i) {
    const weather::CloudLayer& want = w.layers[i];
    const weather::CloudLayer& got = cw.weather.layers[i];
    EXPECT_EQ(got.coverage_channel, static_cast<int>(i)) << "layer " << i << " reads its own slot";
    EXPECT_EQ(got.type, want.type) << i;
    EXPECT_NEAR(got.base_m, want.base_m, 1e-3) << i;
    EXPECT_NEAR(got.top_m, want.top_m, 1e-3) << i;
    EXPECT_NEAR(got.wind.east_mps, want.wind.east_mps, 1e-3) << i;
    EXPECT_NEAR(got.wind.north_mps, want.wind.north_mps, 1e-3) << i;
    EXPECT_NEAR(got.density_scale, want.density_scale, 1e-6 * want.density_scale) << i << ": the water content sent";
  }
  // The map holds each layer's coverage everywhere (no regions).
  for (std::size_t i = 0; i < w.layers.size(); ++i)
    EXPECT_NEAR(cw.map.layer_coverage[4 * (16 * 64 + 40) + i], w.layers[i].coverage, 1e-6) << i;
}

TEST(SimClientCigiHostFrames, CloudLayersAndTheirWindReachTheRenderer) {
  const std::optional<weather::Weather> broken = weather::preset("broken-cumulus");
  ASSERT_TRUE(broken);
  ASSERT_EQ(broken->layers.size(), 2u);
  ASSERT_NE(broken->layers[0].wind.east_mps, 0.0) << "the preset has wind: the test checks its direction";
  const weather::Weather three = three_layers();
  ASSERT_EQ(weather::validate(three), "");
  for (cigi::ByteOrder order : kOrders) {
    expect_weather_round_trip(*broken, order);
    expect_weather_round_trip(three, order);
  }
}

TEST(SimClientCigiHostFrames, FewerLayersInANewWeatherClearTheOldOnes) {
  const weather::Weather three = three_layers();
  weather::Weather one = three;
  one.name = "one";
  one.layers.resize(1);
  for (cigi::ByteOrder order : kOrders) {
    HostFrame first;
    first.host_frame = 1;
    first.pose = pose_at(utc(2026, 6, 21, 10, 17, 42));
    first.weather = &three;
    HostFrame second = first;
    second.host_frame = 2;
    second.weather = &one;
    const cigi::IgState s = apply({first, second}, order);
    EXPECT_TRUE(s.global_layers()[0]);
    EXPECT_FALSE(s.global_layers()[1]);
    EXPECT_FALSE(s.global_layers()[2]);
    EXPECT_EQ(cigi::cigi_weather(s, 0.0, 0.0, 64, 32).weather.layers.size(), 1u);
  }
}

TEST(SimClientCigiHostFrames, MoreThanThreeLayersAreRefused) {
  weather::Weather four = three_layers();
  four.name = "four";
  weather::CloudLayer cc = weather::default_layer(weather::CloudType::Cirrocumulus);
  cc.base_m = 11000.0;
  cc.top_m = 11500.0;
  four.layers.push_back(cc);
  ASSERT_EQ(weather::validate(four), "") << "a weather the renderer draws";
  EXPECT_THROW(global_weather_controls(four), std::invalid_argument);
  HostFrame f;
  f.pose = pose_at(utc(2026, 6, 21, 10, 17, 42));
  f.weather = &four;
  EXPECT_THROW(host_datagram(f, cigi::ByteOrder::Big), std::invalid_argument) << "not sent with a layer missing";
}

}  // namespace
}  // namespace cloudsvc::sim
