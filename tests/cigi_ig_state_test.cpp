// The IG's state from a CIGI host's datagrams (protocol/cigi/cigi_ig_state.h): views built up
// field by field, the ownship, the sun's time, the atmosphere, global and regional cloud
// layers, and the packets refused at this stage.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geodesy/utc_time.h"
#include "cigi_test_support.h"
#include "protocol/cigi/cigi_ig_state.h"

namespace cloudsvc::cigi {
namespace {


TEST(CigiIgState, ViewsAreBuiltFieldByFieldFromTheDefault) {
  const ViewFrustum defaults{-25.0f, 25.0f, 15.0f, -15.0f, 1.0f, 100000.0f};
  IgState s(defaults);
  ASSERT_EQ(s.views().size(), 1u);
  EXPECT_EQ(s.views()[0].frustum, defaults) << "before any view packet: view 0 with the IG's field of view";
  ViewControl left;
  left.view_id = 1;
  left.enable = view_enable::kYaw | view_enable::kY;
  left.yaw_deg = -50.0f;
  left.y_m = -0.5f;
  left.x_m = 99.0f;  // not enabled: not used
  ViewDefinition narrow;
  narrow.view_id = 1;
  narrow.enable = definition_enable::kLeft | definition_enable::kRight;
  narrow.left_deg = -20.0f;
  narrow.right_deg = 20.0f;
  EXPECT_TRUE(s.apply(host_datagram({left, narrow}, 7)).empty());
  EXPECT_EQ(s.last_host_frame(), 7u);
  EXPECT_EQ(s.mode(), IgMode::Operate);
  ASSERT_EQ(s.views().size(), 1u) << "the host's views replace the default one";
  const View v = s.views()[0];
  EXPECT_EQ(v.id, 1);
  EXPECT_EQ(v.yaw_deg, -50.0f);
  EXPECT_EQ(v.y_m, -0.5f);
  EXPECT_EQ(v.x_m, 0.0f);
  EXPECT_EQ(v.frustum.left_deg, -20.0f);
  EXPECT_EQ(v.frustum.right_deg, 20.0f);
  EXPECT_EQ(v.frustum.top_deg, 15.0f) << "not enabled: the default";
  // A definition that would cross the view's other fields is refused whole.
  ViewDefinition bad;
  bad.view_id = 1;
  bad.enable = definition_enable::kLeft;
  bad.left_deg = 40.0f;
  const auto refused = s.apply(host_datagram({bad}));
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_EQ(refused[0], "View Definition of view 1: with the view's other fields no frustum (left < right, bottom < top, near < far)");
  EXPECT_EQ(s.views()[0].frustum.left_deg, -20.0f);
  // ... also for a view not seen before: it is not created.
  bad.view_id = 4;
  bad.left_deg = 45.0f;  // right of the default right edge, 25°
  EXPECT_EQ(s.apply(host_datagram({bad})).size(), 1u);
  EXPECT_EQ(s.views().size(), 1u);
  // At most kMaxViews views.
  std::vector<HostPacket> many;
  for (std::uint16_t id = 10; id < 20; ++id) {
    ViewControl c;
    c.view_id = id;
    many.push_back(c);
  }
  const auto over = s.apply(host_datagram(many));
  EXPECT_EQ(s.views().size(), IgState::kMaxViews);
  ASSERT_EQ(over.size(), 10u - (IgState::kMaxViews - 1));
  EXPECT_EQ(over[0], "View Control of view 17: the IG draws at most 8 views");
}

// Near and far planes: not given, none (0); given one at a time; a far plane must lie
// beyond the near one.
TEST(CigiIgState, NearAndFarPlanes) {
  IgState s;
  EXPECT_EQ(s.views()[0].frustum.near_m, 0.0f);
  EXPECT_EQ(s.views()[0].frustum.far_m, 0.0f) << "no plane until the host gives one";
  ViewDefinition near_only;
  near_only.view_id = 0;
  near_only.enable = definition_enable::kNear;
  near_only.near_m = 600000.0f;
  EXPECT_TRUE(s.apply(host_datagram({near_only})).empty()) << "a near plane with no far plane";
  EXPECT_EQ(s.views()[0].frustum.near_m, 600000.0f);
  ViewDefinition far_before_near;
  far_before_near.view_id = 0;
  far_before_near.enable = definition_enable::kFar;
  far_before_near.far_m = 1000.0f;
  EXPECT_EQ(s.apply(host_datagram({far_before_near})).size(), 1u) << "far within the view's near plane";
  EXPECT_EQ(s.views()[0].frustum.far_m, 0.0f);
  ViewDefinition both;
  both.view_id = 0;
  both.enable = definition_enable::kNear | definition_enable::kFar;
  both.near_m = 0.5f;
  both.far_m = 80000.0f;
  EXPECT_TRUE(s.apply(host_datagram({both})).empty());
  EXPECT_EQ(s.views()[0].frustum.near_m, 0.5f);
  EXPECT_EQ(s.views()[0].frustum.far_m, 80000.0f);
}

// The mirror mode is a View Definition field without an enable bit: every definition sets it,
// in either byte order; the frustum's fields keep their enable bits.
TEST(CigiIgState, MirrorModes) {
  for (const ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
    IgState s;
    EXPECT_EQ(s.views()[0].mirror, 0);
    for (const std::uint8_t mode : {1, 2, 3, 0}) {
      ViewDefinition d;
      d.view_id = 4;
      d.mirror = mode;
      EXPECT_TRUE(s.apply(host_datagram({d}, 1, IgMode::Operate, order)).empty()) << int(mode);
      ASSERT_EQ(s.views().size(), 1u);
      EXPECT_EQ(s.views()[0].id, 4);
      EXPECT_EQ(s.views()[0].mirror, mode);
      EXPECT_EQ(s.views()[0].frustum, ViewFrustum{}) << "no frustum field enabled";
    }
  }
}

TEST(CigiIgState, OwnshipTimeAndAtmosphere) {
  IgState s;
  EXPECT_FALSE(s.ownship());
  EntityControl e;
  e.lat_deg = 47.45;
  e.lon_deg = 8.56;
  e.alt_m = 3000.0;
  e.yaw_deg = 120.0f;
  CelestialSphereControl c;
  c.date_valid = true;
  c.date = 6212026;
  c.hour = 16;
  c.minute = 30;
  AtmosphereControl a;
  a.visibility_m = 25000.0f;
  s.apply(host_datagram({e, c, a}));
  ASSERT_TRUE(s.ownship());
  EXPECT_EQ(*s.ownship(), (OwnshipPose{47.45, 8.56, 3000.0, 0.0, 0.0, 120.0}));
  EXPECT_EQ(s.utc_s(), geo::parse_utc_iso8601("2026-06-21T16:30:00Z"));
  ASSERT_TRUE(s.atmosphere());
  EXPECT_EQ(s.atmosphere()->visibility_m, 25000.0f);
  // A time without a valid date leaves the time as it was.
  c.date_valid = false;
  c.hour = 3;
  s.apply(host_datagram({c}));
  EXPECT_EQ(s.utc_s(), geo::parse_utc_iso8601("2026-06-21T16:30:00Z"));
  EXPECT_EQ(s.datagrams(), 2u);
}

// Atmosphere Control is kept as sent; its generation rises when the visibility changes (the
// haze to redraw), not when the same visibility comes again. A packet with a non-finite field
// is refused by the reader and changes nothing: not its humidity, not the visibility.
TEST(CigiIgState, AtmosphereVisibilityAndANonFiniteOneRefusedWhole) {
  IgState s;
  EXPECT_EQ(s.atmosphere_generation(), 0u);
  AtmosphereControl a;
  a.humidity_pct = 50;
  a.visibility_m = 20000.0f;
  EXPECT_TRUE(s.apply(host_datagram({a})).empty());
  EXPECT_EQ(s.atmosphere_generation(), 1u);
  a.humidity_pct = 60;  // kept, not drawn: no new haze
  s.apply(host_datagram({a}));
  EXPECT_EQ(s.atmosphere_generation(), 1u);
  EXPECT_EQ(s.atmosphere()->humidity_pct, 60);
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    AtmosphereControl b = a;
    b.humidity_pct = 80;
    b.visibility_m = bad;
    DatagramWriter w;
    IgControl c;
    c.host_frame = 9;
    w.add(c);
    w.add(b);
    const HostDatagram d = read_host_datagram(w.bytes());
    ASSERT_EQ(d.rejections.size(), 1u);
    EXPECT_EQ(d.rejections[0].reason, std::string("Atmosphere Control at byte 24: visibility_m is ") +
                                          (std::isnan(bad) ? "nan" : "inf") + " (must be finite)");
    EXPECT_TRUE(s.apply(d).empty());
    EXPECT_EQ(s.last_host_frame(), 9u) << "the rest of the datagram is used";
    ASSERT_TRUE(s.atmosphere());
    EXPECT_EQ(s.atmosphere()->visibility_m, 20000.0f) << "not half-applied";
    EXPECT_EQ(s.atmosphere()->humidity_pct, 60);
    EXPECT_EQ(s.atmosphere_generation(), 1u);
  }
  a.visibility_m = 9000.0f;
  s.apply(host_datagram({a}));
  EXPECT_EQ(s.atmosphere_generation(), 2u);
  EXPECT_EQ(s.atmosphere()->visibility_m, 9000.0f);
}

// The host's frame number and timestamp (the shared-memory slot's sim time) follow its last
// IG Control; a timestamp it marks invalid is none.
TEST(CigiIgState, HostFrameAndTimestamp) {
  IgState s;
  EXPECT_FALSE(s.host_timestamp_s());
  DatagramWriter w;
  IgControl c;
  c.host_frame = 41;
  c.timestamp_valid = true;
  c.timestamp = 1234567;  // 12.34567 s
  w.add(c);
  s.apply(read_host_datagram(w.bytes()));
  EXPECT_EQ(s.last_host_frame(), 41u);
  ASSERT_TRUE(s.host_timestamp_s());
  EXPECT_DOUBLE_EQ(*s.host_timestamp_s(), 12.34567);
  s.apply(host_datagram({}, 42));  // timestamp not valid
  EXPECT_EQ(s.last_host_frame(), 42u);
  EXPECT_FALSE(s.host_timestamp_s());
}

// Global layer 1: a 400 m overcast stratus deck from 800 m.
WeatherControl global_stratus() {
  WeatherControl stratus;
  stratus.layer_id = 1;
  stratus.cloud_type = 10;
  stratus.base_elevation_m = 800.0f;
  stratus.thickness_m = 400.0f;
  stratus.coverage_pct = 100.0f;
  return stratus;
}

// Region 5: 40 x 20 km around 46 N, 7 E.
EnvironmentalRegionControl region_5() {
  EnvironmentalRegionControl r;
  r.region_id = 5;
  r.lat_deg = 46.0;
  r.lon_deg = 7.0;
  r.size_x_m = 40000.0f;
  r.size_y_m = 20000.0f;
  return r;
}

TEST(CigiIgState, GlobalAndRegionalCloudLayers) {
  IgState s;
  const std::uint64_t g0 = s.weather_generation();
  WeatherControl stratus = global_stratus();
  WeatherControl rain;  // layer 4: precipitation, not drawn
  rain.layer_id = 4;
  s.apply(host_datagram({stratus, rain}));
  ASSERT_TRUE(s.global_layers()[0]);
  EXPECT_EQ(s.global_layers()[0]->cloud_type, 10);
  EXPECT_FALSE(s.global_layers()[1]);
  EXPECT_GT(s.weather_generation(), g0);

  // A regional layer needs its region first.
  WeatherControl cb = stratus;
  cb.layer_id = 2;
  cb.cloud_type = 6;
  cb.scope = WeatherScope::Regional;
  cb.entity_or_region_id = 5;
  auto refused = s.apply(host_datagram({cb}));
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_EQ(refused[0], "Weather Control of layer 2 in region 5: no such region (send its Environmental Region Control first)");
  EnvironmentalRegionControl r = region_5();
  r.transition_perimeter_m = 5000.0f;
  EXPECT_TRUE(s.apply(host_datagram({r, cb})).empty());
  ASSERT_EQ(s.regions().size(), 1u);
  EXPECT_EQ(s.regions().at(5).layers[1]->cloud_type, 6);
  EXPECT_FALSE(s.global_layers()[1]) << "a regional layer is not global";

  // Disabling a layer removes it; destroying a region removes it and its layers.
  stratus.enabled = false;
  const std::uint64_t g1 = s.weather_generation();
  r.state = 2;
  s.apply(host_datagram({stratus, r}));
  EXPECT_FALSE(s.global_layers()[0]);
  EXPECT_TRUE(s.regions().empty());
  EXPECT_GT(s.weather_generation(), g1);
}

// Hosts resend their weather every frame: a Weather Control or region that changes nothing
// does not make the weather again (nor repeat its notes); any change does. The host's first
// Weather Control takes the weather over even when it only disables a layer.
TEST(CigiIgState, ResentWeatherIsNotAChange) {
  IgState s;
  WeatherControl off;
  off.layer_id = 2;
  off.enabled = false;
  s.apply(host_datagram({off}));
  const std::uint64_t first = s.weather_generation();
  EXPECT_GT(first, 0u) << "the host's weather, with no cloud on layer 2";
  s.apply(host_datagram({off}, 2));
  EXPECT_EQ(s.weather_generation(), first);

  WeatherControl stratus = global_stratus();
  EnvironmentalRegionControl r = region_5();
  WeatherControl regional = stratus;
  regional.scope = WeatherScope::Regional;
  regional.entity_or_region_id = 5;
  s.apply(host_datagram({stratus, r, regional}, 3));
  const std::uint64_t made = s.weather_generation();
  EXPECT_GT(made, first);
  for (std::uint32_t frame = 4; frame < 10; ++frame) s.apply(host_datagram({stratus, r, regional, off}, frame));
  EXPECT_EQ(s.weather_generation(), made) << "the same packets again";
  stratus.coverage_pct = 60.0f;
  s.apply(host_datagram({stratus, r, regional}, 10));
  EXPECT_GT(s.weather_generation(), made) << "a layer changed";
  const std::uint64_t layer_changed = s.weather_generation();
  r.transition_perimeter_m = 2000.0f;
  s.apply(host_datagram({stratus, r, regional}, 11));
  EXPECT_GT(s.weather_generation(), layer_changed) << "a region changed";
}

}  // namespace
}  // namespace cloudsvc::cigi
