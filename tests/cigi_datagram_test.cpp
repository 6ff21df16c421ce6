// CIGI 3.3 datagrams (protocol/cigi/cigi_datagram.h): every packet the IG honours survives a
// write and a read in both byte orders; bytes laid out by hand from the standard read as
// the standard says; and every kind of bad datagram is named, counted and never half-used.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "protocol/cigi/cigi_datagram.h"

namespace cloudsvc::cigi {
namespace {

IgControl ig_control(std::uint32_t host_frame = 41) {
  IgControl c;
  c.database = -3;
  c.mode = IgMode::Operate;
  c.timestamp_valid = true;
  c.extrapolation = true;
  c.host_frame = host_frame;
  c.timestamp = 123456789;
  c.last_ig_frame = 40;
  return c;
}

std::vector<HostPacket> every_host_packet() {
  EntityControl e;
  e.roll_deg = -12.5f;
  e.pitch_deg = 3.25f;
  e.yaw_deg = 271.0f;
  e.lat_deg = 47.458333333333336;
  e.lon_deg = 8.548055555555555;
  e.alt_m = 2134.56;
  e.entity_type = 737;
  ViewControl v{2, 1, 0x3f, 0, 1.5f, -0.25f, -0.8f, 0.0f, -5.0f, 45.0f};
  ViewDefinition d;
  d.view_id = 2;
  d.group_id = 1;
  d.enable = 0x3f;
  d.reorder = true;
  d.view_type = 5;
  d.pixel_replication = 3;
  d.near_m = 0.5f;
  d.far_m = 80000.0f;
  d.left_deg = -30.0f;
  d.right_deg = 30.0f;
  d.top_deg = 20.0f;
  d.bottom_deg = -15.0f;
  CelestialSphereControl c;
  c.hour = 17;
  c.minute = 45;
  c.date_valid = true;
  c.moon = true;
  c.date = 6212026;  // 2026-06-21
  c.star_intensity_pct = 40.0f;
  AtmosphereControl a{true, 65, 12.5f, 30000.0f, 8.0f, -0.5f, 250.0f, 1002.0f};
  EnvironmentalRegionControl r;
  r.region_id = 7;
  r.merge = 0b0101;
  r.lat_deg = 46.9;
  r.lon_deg = 7.4;
  r.size_x_m = 50000.0f;
  r.size_y_m = 30000.0f;
  r.corner_radius_m = 5000.0f;
  r.rotation_deg = -30.0f;
  r.transition_perimeter_m = 8000.0f;
  WeatherControl w;
  w.entity_or_region_id = 7;
  w.layer_id = 2;
  w.humidity_pct = 80;
  w.scud = true;
  w.random_lightning = true;
  w.cloud_type = 9;
  w.scope = WeatherScope::Regional;
  w.severity = 3;
  w.coverage_pct = 75.0f;
  w.base_elevation_m = 1200.0f;
  w.thickness_m = 600.0f;
  w.transition_band_m = 100.0f;
  w.wind_horizontal_mps = 12.0f;
  w.wind_direction_deg = 270.0f;
  w.aerosol_gpm3 = 0.25f;
  return {e, v, d, c, a, r, w};
}

TEST(CigiDatagram, EveryHonouredPacketSurvivesBothByteOrders) {
  for (ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
    DatagramWriter w(order);
    w.add(ig_control());
    for (const HostPacket& p : every_host_packet()) w.add(p);
    EXPECT_EQ(w.bytes().size(), 24u + 48 + 32 + 32 + 16 + 32 + 48 + 56);
    const HostDatagram d = read_host_datagram(w.bytes());
    ASSERT_TRUE(d.usable) << d.rejections.front().reason;
    EXPECT_EQ(d.order, order);
    EXPECT_EQ(d.ig_control, ig_control());
    EXPECT_TRUE(d.rejections.empty()) << d.rejections.front().reason;
    EXPECT_EQ(d.packets, every_host_packet());
    EXPECT_EQ(d.ignored, 0u);
  }
}

// IG Control and Entity Control written byte by byte from the standard's layout, big-endian,
// then the same little-endian: both read as the standard says.
TEST(CigiDatagram, BytesLaidOutByHandReadAsTheStandardSays) {
  for (bool big : {true, false}) {
    std::vector<std::uint8_t> d(24 + 48, 0);
    const auto put = [&](std::size_t at, std::uint64_t v, int n) {
      for (int k = 0; k < n; ++k) d[at + (big ? n - 1 - k : k)] = static_cast<std::uint8_t>(v >> (8 * k));
    };
    d[0] = 1, d[1] = 24, d[2] = 3, d[3] = 0xfe;  // IG Control, CIGI 3, database -2
    d[4] = (3 << 4) | (1 << 2) | 1;              // minor 3, timestamp valid, operate
    put(6, 0x8000, 2);
    put(8, 1001, 4), put(12, 500, 4), put(16, 999, 4);
    d[24] = 2, d[25] = 48;  // Entity Control, entity 0, active
    d[28] = 1;
    put(24 + 12, std::bit_cast<std::uint32_t>(5.0f), 4);
    put(24 + 16, std::bit_cast<std::uint32_t>(-2.5f), 4);
    put(24 + 20, std::bit_cast<std::uint32_t>(90.0f), 4);
    put(24 + 24, std::bit_cast<std::uint64_t>(-33.9461), 8);
    put(24 + 32, std::bit_cast<std::uint64_t>(151.1772), 8);
    put(24 + 40, std::bit_cast<std::uint64_t>(6.0), 8);
    const HostDatagram r = read_host_datagram(d);
    ASSERT_TRUE(r.usable) << r.rejections.front().reason;
    EXPECT_EQ(r.order, big ? ByteOrder::Big : ByteOrder::Little);
    EXPECT_EQ(r.ig_control.minor_version, 3);
    EXPECT_EQ(r.ig_control.database, -2);
    EXPECT_TRUE(r.ig_control.timestamp_valid);
    EXPECT_EQ(r.ig_control.mode, IgMode::Operate);
    EXPECT_EQ(r.ig_control.host_frame, 1001u);
    EXPECT_EQ(r.ig_control.timestamp, 500u);
    EXPECT_EQ(r.ig_control.last_ig_frame, 999u);
    ASSERT_EQ(r.packets.size(), 1u);
    const auto& e = std::get<EntityControl>(r.packets[0]);
    EXPECT_EQ(e.state, 1);
    EXPECT_EQ(e.roll_deg, 5.0f);
    EXPECT_EQ(e.pitch_deg, -2.5f);
    EXPECT_EQ(e.yaw_deg, 90.0f);
    EXPECT_EQ(e.lat_deg, -33.9461);
    EXPECT_EQ(e.lon_deg, 151.1772);
    EXPECT_EQ(e.alt_m, 6.0);
  }
}

TEST(CigiDatagram, StartOfFrameAndIgMessagesSurviveAndTextIsCut) {
  for (ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
    DatagramWriter w(order);
    StartOfFrame sof;
    sof.ig_frame = 77;
    sof.last_host_frame = 41;
    sof.timestamp_valid = true;
    sof.timestamp = 4242;
    w.add(sof);
    w.add(IgMessage{3, "Entity Control at byte 24: lat_deg 95 out of range [-90, 90]"});
    w.add(IgMessage{4, std::string(150, 'x')});
    w.add(IgMessage{5, ""});
    const IgDatagram d = read_ig_datagram(w.bytes());
    ASSERT_TRUE(d.usable) << d.rejections.front().reason;
    EXPECT_EQ(d.start_of_frame, sof);
    ASSERT_EQ(d.messages.size(), 3u);
    EXPECT_EQ(d.messages[0], (IgMessage{3, "Entity Control at byte 24: lat_deg 95 out of range [-90, 90]"}));
    EXPECT_EQ(d.messages[1].text, std::string(kMaxIgMessageText, 'x'));
    EXPECT_EQ(d.messages[2], (IgMessage{5, ""}));
    // Sizes: 24, then 4 + text + NUL rounded up to 8 (64 + 4 + 1 -> 72; 104; 8).
    EXPECT_EQ(w.bytes()[24 + 1], 72);
    EXPECT_EQ(w.bytes()[24 + 72 + 1], 104);
    EXPECT_EQ(w.bytes()[24 + 72 + 104 + 1], 8);
  }
}

std::vector<std::uint8_t> with(std::vector<HostPacket> packets, ByteOrder order = ByteOrder::Little) {
  DatagramWriter w(order);
  w.add(ig_control());
  for (const HostPacket& p : packets) w.add(p);
  return w.bytes();
}

std::string only_rejection(const std::vector<std::uint8_t>& bytes) {
  const HostDatagram d = read_host_datagram(bytes);
  if (d.rejections.size() != 1) return "(" + std::to_string(d.rejections.size()) + " rejections)";
  return d.rejections[0].reason;
}

TEST(CigiDatagram, AnUnusableDatagramIsNamedAndNothingOfItIsUsed) {
  const auto unusable = [](const std::vector<std::uint8_t>& bytes) {
    const HostDatagram d = read_host_datagram(bytes);
    EXPECT_FALSE(d.usable);
    EXPECT_TRUE(d.packets.empty());
    return d.rejections.size() == 1 ? d.rejections[0].reason : std::string("?");
  };
  EXPECT_EQ(unusable({}), "the datagram does not start with IG Control (opcode 1)");
  EXPECT_EQ(unusable({1}), "the datagram does not start with IG Control (opcode 1)");
  std::vector<std::uint8_t> d = with({EntityControl{}});
  EXPECT_EQ(unusable(std::vector<std::uint8_t>(d.begin() + 24, d.end())), "the datagram does not start with IG Control (opcode 1)");
  EXPECT_EQ(unusable(std::vector<std::uint8_t>(d.begin(), d.begin() + 20)), "IG Control of 24 bytes in a datagram of 20 (CIGI 3.2 and 3.3: 24)");
  auto edit = [&](std::size_t at, std::uint8_t v) {
    std::vector<std::uint8_t> e = d;
    e[at] = v;
    return e;
  };
  EXPECT_EQ(unusable(edit(1, 16)), "IG Control of 16 bytes in a datagram of 72 (CIGI 3.2 and 3.3: 24)");
  EXPECT_EQ(unusable(edit(2, 4)), "CIGI major version 4 (this IG speaks CIGI 3.3)");
  EXPECT_EQ(unusable(edit(4, 0x11)), "CIGI minor version 3.1 (this IG speaks CIGI 3.2 and 3.3)");
  EXPECT_EQ(unusable(edit(7, 0x81)), "byte-swap magic 0081 (expected 8000 in either byte order)");
  EXPECT_EQ(unusable(edit(4, (3 << 4) | 3)), "IG Control: ig_mode 3 out of range [0, 2]");
  // CIGI 3.2 hosts are read too (the same IG Control).
  EXPECT_TRUE(read_host_datagram(edit(4, (2 << 4) | 1)).usable);
}

TEST(CigiDatagram, BadPacketsAreSkippedByTheirSizeAndTheRestIsRead) {
  EntityControl e;
  e.lat_deg = 47.0;
  const std::vector<std::uint8_t> good = with({e});
  // An unknown opcode between IG Control and Entity Control: skipped by its size.
  std::vector<std::uint8_t> d(good.begin(), good.begin() + 24);
  d.insert(d.end(), {77, 8, 1, 2, 3, 4, 5, 6});
  d.insert(d.end(), good.begin() + 24, good.end());
  HostDatagram r = read_host_datagram(d);
  ASSERT_EQ(r.rejections.size(), 1u);
  EXPECT_EQ(r.rejections[0].reason, "unknown packet opcode 77 at byte 24 (8 bytes); skipped");
  EXPECT_EQ(r.rejections[0].offset, 24u);
  ASSERT_EQ(r.packets.size(), 1u);
  EXPECT_EQ(std::get<EntityControl>(r.packets[0]).lat_deg, 47.0);

  // A known packet of the wrong size: skipped by its size.
  d = std::vector<std::uint8_t>(good.begin(), good.begin() + 24);
  d.insert(d.end(), {16, 24});
  d.resize(d.size() + 22, 0);
  d.insert(d.end(), good.begin() + 24, good.end());
  r = read_host_datagram(d);
  ASSERT_EQ(r.rejections.size(), 1u);
  EXPECT_EQ(r.rejections[0].reason, "View Control at byte 24: 24 bytes (CIGI 3.3: 32); skipped");
  EXPECT_EQ(r.packets.size(), 1u);

  // A size that lies (past the end) or is below a header: the datagram ends there.
  d = good;
  d[25] = 200;
  EXPECT_EQ(only_rejection(d), "Entity Control at byte 24: size 200 runs past the datagram's end (48 bytes left); the rest of the datagram is skipped");
  d[25] = 0;
  EXPECT_EQ(only_rejection(d), "Entity Control at byte 24: size 0 (a packet is at least 2 bytes); the rest of the datagram is skipped");
  d = good;
  d.push_back(2);
  EXPECT_EQ(only_rejection(d), "1 byte after the last packet, shorter than a packet header");
  EXPECT_EQ(read_host_datagram(d).packets.size(), 1u) << "the packets before it are read";

  // Accepted and ignored: another entity, component controls, other host packets, user-defined.
  EntityControl other;
  other.entity_id = 12;
  other.lat_deg = std::numeric_limits<double>::quiet_NaN();  // not checked: not drawn
  d = with({other});
  d.insert(d.end(), {5, 16});  // Short Component Control
  d.resize(d.size() + 14, 0);
  d.insert(d.end(), {230, 8, 0, 0, 0, 0, 0, 0});  // user-defined
  r = read_host_datagram(d);
  EXPECT_TRUE(r.rejections.empty());
  EXPECT_TRUE(r.packets.empty());
  EXPECT_EQ(r.ignored, 3u);

  // Fields left out by the enable bits are not used: whatever the host sent, they read as 0.
  ViewDefinition near_only;
  near_only.enable = definition_enable::kNear;
  near_only.near_m = 0.25f;
  near_only.far_m = std::numeric_limits<float>::quiet_NaN();
  near_only.left_deg = 400.0f;
  r = read_host_datagram(with({near_only}));
  ASSERT_TRUE(r.rejections.empty()) << r.rejections[0].reason;
  ASSERT_EQ(r.packets.size(), 1u);
  EXPECT_EQ(std::get<ViewDefinition>(r.packets[0]).near_m, 0.25f);
  EXPECT_EQ(std::get<ViewDefinition>(r.packets[0]).far_m, 0.0f);
  EXPECT_EQ(std::get<ViewDefinition>(r.packets[0]).left_deg, 0.0f);

  // A packet the IG ignores still has its standard size.
  d = with({});
  d.insert(d.end(), {4, 16});  // Component Control is 32 bytes
  d.resize(d.size() + 14, 0);
  EXPECT_EQ(only_rejection(d), "Component Control at byte 24: 16 bytes (CIGI 3.3: 32); skipped");

  // An IG -> host packet and a second IG Control from the host.
  d = with({});
  d.insert(d.end(), good.begin(), good.begin() + 24);
  EXPECT_EQ(only_rejection(d), "IG Control at byte 24: a second IG Control in one datagram; skipped");
  DatagramWriter sof(ByteOrder::Little);
  sof.add(StartOfFrame{});
  d = with({});
  d.insert(d.end(), sof.bytes().begin(), sof.bytes().end());
  EXPECT_EQ(only_rejection(d), "Start of Frame at byte 24: an IG -> host packet from the host; skipped");
}

TEST(CigiDatagram, FieldsOutOfRangeRejectTheWholePacket) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto reason = [](HostPacket p) { return only_rejection(with({p})); };
  EntityControl e;
  e.lat_deg = 95.0;
  EXPECT_EQ(reason(e), "Entity Control at byte 24: lat_deg 95 out of range [-90, 90]");
  e.lat_deg = nan;
  EXPECT_EQ(reason(e), "Entity Control at byte 24: lat_deg is nan (must be finite)");
  e = EntityControl{};
  e.pitch_deg = std::numeric_limits<float>::infinity();
  EXPECT_EQ(reason(e), "Entity Control at byte 24: pitch_deg is inf (must be finite)");
  e = EntityControl{};
  e.alt_m = 1e6;
  EXPECT_EQ(reason(e), "Entity Control at byte 24: alt_m 1000000 out of range [-500, 100000]");
  ViewControl v;
  v.entity_id = 3;
  EXPECT_EQ(reason(v), "View Control at byte 24: entity_id 3: views are attached to the ownship (0)");
  ViewDefinition vd;
  vd.enable = 0x3f;
  vd.near_m = 1.0f;
  vd.far_m = 1000.0f;
  vd.left_deg = 20.0f;
  vd.right_deg = -20.0f;
  vd.top_deg = 10.0f;
  vd.bottom_deg = -10.0f;
  EXPECT_EQ(reason(vd), "View Definition at byte 24: right_deg -20 not right of left_deg 20");
  vd.left_deg = -89.0f;
  EXPECT_EQ(reason(vd), "View Definition at byte 24: left_deg -89 out of range [-85, 85]");
  vd.left_deg = -20.0f;
  vd.right_deg = 20.0f;
  vd.orthographic = true;
  EXPECT_EQ(reason(vd), "View Definition at byte 24: orthographic projection (the IG draws perspective views)");
  CelestialSphereControl c;
  c.date_valid = true;
  c.date = 2302026;  // 30 February
  EXPECT_EQ(reason(c), "Celestial Sphere Control at byte 24: date 2302026 is not a date MMDDYYYY in 1900..2199");
  c.date = 2292028;  // 29 February of a leap year
  EXPECT_TRUE(read_host_datagram(with({c})).rejections.empty());
  c.hour = 24;
  EXPECT_EQ(reason(c), "Celestial Sphere Control at byte 24: hour 24 out of range [0, 23]");
  WeatherControl w;
  w.coverage_pct = 120.0f;
  EXPECT_EQ(reason(w), "Weather Control at byte 24: coverage_pct 120 out of range [0, 100]");
  w.coverage_pct = 50.0f;
  w.cloud_type = 12;  // IG-defined: this IG has none
  EXPECT_EQ(reason(w), "Weather Control at byte 24: cloud_type 12 out of range [0, 10]");
  w.cloud_type = 7;
  w.base_elevation_m = 19000.0f;
  w.thickness_m = 2000.0f;
  EXPECT_EQ(reason(w), "Weather Control at byte 24: thickness_m 2000 out of range [0, 1000]");
  EnvironmentalRegionControl r;
  r.size_x_m = 1000.0f;
  r.size_y_m = 800.0f;
  r.corner_radius_m = 500.0f;
  EXPECT_EQ(reason(r), "Environmental Region Control at byte 24: corner_radius_m 500 out of range [0, 400]");
  AtmosphereControl a;
  a.humidity_pct = 101;
  EXPECT_EQ(reason(a), "Atmosphere Control at byte 24: humidity_pct 101 out of range [0, 100]");
}

// Random bytes after a sound IG Control, and random bytes altogether: every datagram reads to
// a result (no crash, no hang), and every packet kept passed its checks.
TEST(CigiDatagram, RandomBytesNeverBreakTheReader) {
  std::mt19937 rng(7);
  const std::vector<std::uint8_t> head = with({});
  for (int i = 0; i < 20000; ++i) {
    std::vector<std::uint8_t> d = i % 2 ? head : std::vector<std::uint8_t>{};
    const std::size_t n = rng() % 200;
    for (std::size_t k = 0; k < n; ++k) d.push_back(static_cast<std::uint8_t>(rng()));
    const HostDatagram r = read_host_datagram(d);
    if (!r.usable) {
      EXPECT_TRUE(r.packets.empty());
    }
    EXPECT_LE(r.packets.size() + r.rejections.size() + r.ignored, d.size() / 2 + 1);
  }
}

}  // namespace
}  // namespace cloudsvc::cigi
