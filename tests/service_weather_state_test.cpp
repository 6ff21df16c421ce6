// Weather state of a running `cloudsvc serve`, judged by the frames it renders (64x36,
// read back from the shared-memory ring): a rejected WeatherMapTile or WeatherLayers leaves
// the frame exactly as before, an accepted tile changes it. Tiles fade in over the
// service's 30 s transition (weather/weather_timeline.h), so every tile is sent while the
// pose on screen is at T and judged in a frame at T + 600 s; the simulation time (cloud
// animation) stays 0 and the wind is zero, so only the weather and the sun differ.
//
// Two renders of the same state differ slightly (the march jitter follows the frame
// number): measured twins differ by 0.0004-0.002 in cloud fraction (of 0.80) and
// 0.03-0.12 % in mean luminance. "As before" therefore means within 0.01 and 0.5 %; the
// rejected messages, had they been applied, would have moved the cloud fraction by more
// than 0.1 (the last step applies the coverage-1 tile without its bad value: 0.80 -> 0.97).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "service_test_support.h"
#include "shm_frame_stats.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

constexpr double kT = 1782043200.0;  // 2026-06-21T12:00:00Z, s

// Below a cumulus layer near Zurich, looking 20 deg up into it (the whole view above the
// horizon: every pixel could show cloud).
protocol::Pose pose_at(double utc_s) {
  protocol::Pose p;
  p.sim_time_s = 0.0;
  p.utc_unix_s = utc_s;
  p.lat_deg = 47.45;
  p.lon_deg = 8.56;
  p.alt_m = 600.0;
  p.heading_deg = 200.0;
  p.pitch_deg = 20.0;
  p.flags = protocol::pose_flag::kTeleport;  // no temporal history: each frame on its own
  return p;
}

// Renders `p` and reads the frame back from the ring.
ShmFrame render(ServiceConnection& c, const ServiceProcess& svc, const protocol::Pose& p) {
  c.send(p);
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  ShmFrame f;
  EXPECT_TRUE(read_frame(svc.shm_name(), ready.frame_number, f)) << "frame " << ready.frame_number;
  return f;
}

// Sends m and returns the Error answering it (a test failure if a Stats sync comes first).
protocol::Error expect_rejected(ServiceConnection& c, const protocol::Message& m) {
  const std::uint64_t seq = c.send(m);
  c.send(protocol::StatsRequest{});
  for (;;) {
    auto r = c.receive(10s);
    if (!r) break;
    if (auto* e = std::get_if<protocol::Error>(&*r)) {
      EXPECT_EQ(e->answers_seq, seq);
      c.receive_until<protocol::Stats>(10s);
      return *e;
    }
    if (std::holds_alternative<protocol::Stats>(*r)) break;
  }
  ADD_FAILURE() << protocol::message_name(m) << " was not rejected";
  return {};
}

// Sends m and checks that no Error answers it before a Stats round trip.
void expect_accepted(ServiceConnection& c, const protocol::Message& m) {
  c.send(m);
  c.send(protocol::StatsRequest{});
  for (;;) {
    auto r = c.receive(10s);
    ASSERT_TRUE(r.has_value()) << "no Stats answer";
    if (auto* e = std::get_if<protocol::Error>(&*r)) FAIL() << "rejected: " << e->text;
    if (std::holds_alternative<protocol::Stats>(*r)) return;
  }
}

protocol::WeatherLayers cumulus_layer() {
  protocol::WeatherLayers w;
  w.layers = {protocol::CloudLayer{7, 1000.0, 2500.0, 0.25, 1.0, 20.0, 0.0, 0.0}};
  w.map_seed = 7;
  return w;
}

// A coverage tile over central Europe (lat 40..55, lon 0..20), valid at T.
protocol::WeatherMapTile coverage_tile(float value) {
  protocol::WeatherMapTile t;
  t.lat_min_deg = 40.0;
  t.lat_max_deg = 55.0;
  t.lon_min_deg = 0.0;
  t.lon_max_deg = 20.0;
  t.width = 8;
  t.height = 8;
  t.channels = protocol::tile_channel::kCoverage;
  t.valid_at_utc_s = kT;
  t.data.assign(64, value);
  return t;
}

// Same weather up to the frame-to-frame jitter (tolerances in the file comment).
void expect_as_before(const FrameStats& now, const FrameStats& before, const char* what) {
  EXPECT_EQ(now.nonfinite, 0u) << what;
  EXPECT_NEAR(now.cloud_fraction, before.cloud_fraction, 0.01) << what;
  EXPECT_NEAR(now.mean_luminance, before.mean_luminance, 0.005 * before.mean_luminance) << what;
}

TEST(ServiceWeatherState, RejectedTileOrLayersLeaveTheFrameAsBeforeAndAnAcceptedTileChangesIt) {
  ServiceProcess svc("weather_state");
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "weather-state");
  expect_accepted(c, cumulus_layer());
  render(c, svc, pose_at(kT));
  const ShmFrame before = render(c, svc, pose_at(kT + 600.0));
  const FrameStats s0 = stats_of(before);
  RecordProperty("cloud_fraction_before", std::to_string(s0.cloud_fraction));
  RecordProperty("mean_luminance_before", std::to_string(s0.mean_luminance));
  ASSERT_EQ(s0.nonfinite, 0u);
  ASSERT_GT(s0.cloud_fraction, 0.05) << "the view must see some of the layer";
  ASSERT_LT(s0.cloud_fraction, 0.95) << "the view must see gaps in the layer";
  const FrameStats twin = stats_of(render(c, svc, pose_at(kT + 600.0)));
  RecordProperty("cloud_fraction_twin", std::to_string(twin.cloud_fraction));
  RecordProperty("mean_luminance_twin", std::to_string(twin.mean_luminance));
  expect_as_before(twin, s0, "same state rendered twice");

  // Tiles that would fill the sky (coverage 1) if any of their values were taken.
  render(c, svc, pose_at(kT));  // "now" for the tiles
  auto bad = coverage_tile(1.0f);
  bad.data[27] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(expect_rejected(c, bad).code, protocol::ErrorCode::InvalidField);
  bad = coverage_tile(1.0f);
  bad.data.pop_back();  // 63 values for 8 x 8
  EXPECT_EQ(expect_rejected(c, bad).code, protocol::ErrorCode::InvalidField);
  bad = coverage_tile(1.0f);
  bad.data[3] = 1.5f;  // outside [0, 1]
  EXPECT_EQ(expect_rejected(c, bad).code, protocol::ErrorCode::InvalidField);
  // An overcast stack whose second layer overlaps the first.
  protocol::WeatherLayers overlap;
  overlap.layers = {protocol::CloudLayer{10, 300.0, 1500.0, 1.0, 2.0, 20.0, 0.0, 0.0},
                    protocol::CloudLayer{8, 1400.0, 3000.0, 1.0, 2.0, 20.0, 0.0, 0.0}};
  overlap.map_seed = 99;
  EXPECT_EQ(expect_rejected(c, overlap).code, protocol::ErrorCode::InvalidField);
  const ShmFrame after_rejects = render(c, svc, pose_at(kT + 600.0));
  expect_as_before(stats_of(after_rejects), s0, "after the rejected tiles and layers");

  // A valid tile clearing the area (coverage 0) is applied: the layer is gone from the view.
  render(c, svc, pose_at(kT));
  expect_accepted(c, coverage_tile(0.0f));
  const ShmFrame cleared = render(c, svc, pose_at(kT + 600.0));
  const FrameStats s1 = stats_of(cleared);
  RecordProperty("cloud_fraction_cleared", std::to_string(s1.cloud_fraction));
  RecordProperty("mean_luminance_cleared", std::to_string(s1.mean_luminance));
  EXPECT_LT(s1.cloud_fraction, 0.25 * s0.cloud_fraction);
  EXPECT_GT(std::abs(s1.mean_luminance - s0.mean_luminance), 0.05 * s0.mean_luminance);

  // The same tile as the rejected ones, without the bad value: the layer fills the view.
  render(c, svc, pose_at(kT));
  expect_accepted(c, coverage_tile(1.0f));
  const FrameStats s2 = stats_of(render(c, svc, pose_at(kT + 600.0)));
  RecordProperty("cloud_fraction_filled", std::to_string(s2.cloud_fraction));
  EXPECT_GT(s2.cloud_fraction, s0.cloud_fraction + 0.1);
  EXPECT_EQ(svc.stop(), 0);
}

// A ground-albedo tile (snow, 0.8) over the view brightens the ground from the next frame,
// whatever its valid-at time (docs/PROTOCOL.md); a bad one is rejected and changes nothing.
// Clear sky, 600 m over Zurich looking 60 deg down.
TEST(ServiceWeatherState, GroundAlbedoTileAppliesFromTheNextFrame) {
  ServiceProcess svc("albedo_tile");
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "albedo-tile");
  expect_accepted(c, protocol::WeatherLayers{});
  protocol::Pose down = pose_at(kT);
  down.pitch_deg = -60.0;
  const FrameStats land = stats_of(render(c, svc, down));
  ASSERT_EQ(land.nonfinite, 0u);
  protocol::WeatherMapTile snow = coverage_tile(0.8f);
  snow.channels = protocol::tile_channel::kGroundAlbedo;
  snow.valid_at_utc_s = kT + 86400.0;  // tomorrow: the albedo does not wait for it
  snow.data[5] = 1.5f;
  EXPECT_EQ(expect_rejected(c, snow).code, protocol::ErrorCode::InvalidField);
  expect_as_before(stats_of(render(c, svc, down)), land, "after the rejected albedo tile");
  snow.data[5] = 0.8f;
  expect_accepted(c, snow);
  const FrameStats white = stats_of(render(c, svc, down));
  RecordProperty("mean_luminance_land", std::to_string(land.mean_luminance));
  RecordProperty("mean_luminance_snow", std::to_string(white.mean_luminance));
  EXPECT_EQ(white.nonfinite, 0u);
  // the land default's green albedo is 0.12: snow is ~6 times as bright, less the air's light
  EXPECT_GT(white.mean_luminance, 3.0 * land.mean_luminance);
  EXPECT_EQ(svc.stop(), 0);
}

// WeatherLayers.visibility_m, m: outside [1000 m, 1000 km] the message is refused naming the
// field; within, it is taken and drawn.
TEST(ServiceWeatherState, AVisibilityOutsideItsRangeIsRejectedAndOneWithinIsTaken) {
  ServiceProcess svc("visibility");
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "visibility");
  protocol::WeatherLayers fog = cumulus_layer();
  fog.visibility_m = 300.0;
  const protocol::Error e = expect_rejected(c, fog);
  EXPECT_EQ(e.code, protocol::ErrorCode::InvalidField);
  EXPECT_EQ(e.text.rfind("WeatherLayers.visibility_m 300 out of range", 0), 0u) << e.text;
  protocol::WeatherLayers hazy = cumulus_layer();
  hazy.visibility_m = 5000.0;
  expect_accepted(c, hazy);
  EXPECT_EQ(stats_of(render(c, svc, pose_at(kT))).nonfinite, 0u);
  EXPECT_EQ(svc.stop(), 0);
}

}  // namespace
}  // namespace cloudsvc::test
