// Codec: round trips of every message, semantic validation of every field class, and the
// verifier against raw, truncated and randomly mutated payloads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <set>

#include "protocol/codec.h"
#include "protocol/framing.h"
#include "protocol/limits.h"
#include "protocol/validate.h"
#include "protocol/weather_conversion.h"
#include "protocol/wire.h"
#include "weather/map_tile.h"

namespace cloudsvc::protocol {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- one valid instance of every message --------------------------------------------

Pose sample_pose() {
  Pose p;
  p.sim_time_s = 1234.5;
  p.utc_unix_s = 1718000000.25;
  p.lat_deg = 47.123456789012;
  p.lon_deg = -122.987654321098;
  p.alt_m = 3048.75;
  p.heading_deg = 271.5;
  p.pitch_deg = -3.25;
  p.roll_deg = 15.0;
  p.velocity_enu = VelocityEnu{-120.5, 10.25, -2.5};
  p.flags = pose_flag::kTeleport;
  return p;
}

WeatherLayers sample_layers() {
  WeatherLayers w;
  w.map_seed = 0xdeadbeef;
  w.ground_albedo = 0.8;
  w.visibility_m = 25000.5;
  w.layers.push_back(CloudLayer{9, 800.0, 1500.0, 0.6, 1.5, 12.0, 5.0, -3.0});
  w.layers.push_back(CloudLayer{7, 1500.0, 3200.0, 0.35, 1.0, 20.0, 8.5, 1.25});
  w.layers.push_back(CloudLayer{5, 9000.0, 10500.0, 0.2, 0.3, 40.0, 30.0, 20.0});
  return w;
}

WeatherMapTile sample_tile() {
  WeatherMapTile t;
  t.lat_min_deg = 45.0;
  t.lat_max_deg = 48.5;
  t.lon_min_deg = 170.0;  // crosses the antimeridian: 170 E .. 170 W
  t.lon_max_deg = 190.0;
  t.width = 5;
  t.height = 3;
  t.channels = tile_channel::kCoverage | tile_channel::kDensity;
  t.valid_at_utc_s = 1718006400.0;
  for (std::uint32_t i = 0; i < t.width * t.height * 2; ++i) {
    t.data.push_back(static_cast<float>(i % 7) / 6.0f);
  }
  return t;
}

FrameReady sample_frame_ready() {
  FrameReady f;
  f.frame_number = 5'000'000'001ull;
  f.request_id = 42;
  f.pose = sample_pose();
  f.sim_time_s = f.pose.sim_time_s;
  f.shm_slot = 2;
  f.width = 1920;
  f.height = 1080;
  f.render_ms = 16.25;
  f.latency_ms = 33.5;
  f.file_path = "/tmp/frames/frame_000042.exr";
  return f;
}

std::vector<Message> sample_messages() {
  SetView view;
  view.width = 1920;
  view.height = 1080;
  view.hfov_deg = 75.5;
  view.sinks = sink::kShm | sink::kFile;
  view.shm_format = ShmPixelFormat::Rgba8Srgb;
  view.file_dir = "/tmp/frames ünïcode";
  view.file_format = FileFormat::Exr;
  view.quality_preset = "high";

  Welcome welcome;
  welcome.service_version = "0.1.0";
  welcome.capabilities = capability::kAll;
  welcome.minor = 3;

  Pose bare;  // no optional fields, all defaults
  bare.lat_deg = -90.0;
  bare.lon_deg = 180.0;

  FrameReady no_sinks = sample_frame_ready();
  no_sinks.shm_slot.reset();
  no_sinks.file_path.reset();
  no_sinks.request_id = 0;
  no_sinks.pose.utc_unix_s.reset();

  return {
      Hello{1, 0, "flightsim-host ✈", capability::kSinkShm | capability::kStats},
      welcome,
      view,
      sample_pose(),
      bare,
      SetTime{1718000000.125},
      sample_layers(),
      WeatherLayers{.layers = {}, .map_seed = 7, .ground_albedo = std::nullopt, .visibility_m = std::nullopt},
      sample_tile(),
      RenderRequest{0xffff'ffff'ffff'fff0ull},
      sample_frame_ready(),
      no_sinks,
      Error{ErrorCode::InvalidField, "Pose.lat_deg 91 out of range [-90, 90]", 17},
      StatsRequest{},
      Stats{123456, 29.97, 200000, 1234, 3, 812.5},
  };
}

DecodeResult round(const Message& m, std::uint64_t seq = 7) { return decode(encode(m, seq)); }

TEST(ProtocolCodec, RoundTripsEveryMessageType) {
  std::set<std::size_t> types;
  std::uint64_t seq = 1;
  for (const Message& m : sample_messages()) {
    SCOPED_TRACE(std::string(message_name(m)));
    ASSERT_EQ(validate(m), std::nullopt);
    const DecodeResult r = round(m, seq);
    ASSERT_TRUE(r.ok()) << r.error_text;
    EXPECT_EQ(r.seq, seq);
    EXPECT_EQ(*r.message, m);
    EXPECT_EQ(r.message->index(), m.index());
    types.insert(m.index());
    seq = seq * 31 + 0x1234567890ull;  // large sequence numbers survive too
  }
  EXPECT_EQ(types.size(), std::variant_size_v<Message>);
}

// Forecast weather (minor 2): layers that read a layer-coverage slot and tiles that carry
// slots, with or without weather-map channels, survive the wire; an old peer's layers and
// tiles (fields absent) read as coverage_channel -1 and no slots.
TEST(ProtocolCodec, ForecastLayerCoverageRoundTrips) {
  WeatherLayers w = sample_layers();
  w.layers[0].coverage_channel = 0;
  w.layers[2].coverage_channel = 3;
  const DecodeResult rl = round(w);
  ASSERT_TRUE(rl.ok()) << rl.error_text;
  EXPECT_EQ(std::get<WeatherLayers>(*rl.message), w);
  EXPECT_EQ(std::get<WeatherLayers>(*rl.message).layers[1].coverage_channel, -1);
  for (std::uint8_t channels : {std::uint8_t{0}, tile_channel::kCoverage}) {
    WeatherMapTile t = sample_tile();
    t.channels = channels;
    t.layer_channels = 0b1001;
    t.data.assign(static_cast<std::size_t>(t.width) * t.height * t.channel_count(), 0.25f);
    ASSERT_EQ(validate(t), std::nullopt);
    const DecodeResult rt = round(t);
    ASSERT_TRUE(rt.ok()) << rt.error_text;
    EXPECT_EQ(std::get<WeatherMapTile>(*rt.message), t);
  }
  const DecodeResult old = round(sample_tile());
  EXPECT_EQ(std::get<WeatherMapTile>(*old.message).layer_channels, 0);
}

// WeatherLayers.visibility_m (m): set, it survives the wire bit-exactly and becomes the
// weather's; absent (a client that does not send it, or an older writer, whose table ends
// at ground_albedo), it reads as unset: the service's own haze.
TEST(ProtocolCodec, VisibilityRoundTripsAndReadsAsUnsetWhenAbsent) {
  WeatherLayers w = sample_layers();
  w.visibility_m = 0.1 + 12345.6;
  const DecodeResult set = round(w);
  ASSERT_TRUE(set.ok()) << set.error_text;
  const auto& back = std::get<WeatherLayers>(*set.message).visibility_m;
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(std::memcmp(&*back, &*w.visibility_m, sizeof(double)), 0);
  EXPECT_EQ(to_weather(w).visibility_m, w.visibility_m);
  EXPECT_EQ(to_message(to_weather(w)), w);

  w.visibility_m.reset();
  const DecodeResult unset = round(w);
  ASSERT_TRUE(unset.ok()) << unset.error_text;
  EXPECT_FALSE(std::get<WeatherLayers>(*unset.message).visibility_m.has_value());
  EXPECT_FALSE(to_weather(w).visibility_m.has_value());

  flatbuffers::FlatBufferBuilder b;  // the table as written before visibility_m existed
  const std::vector<flatbuffers::Offset<wire::CloudLayer>> none;
  wire::WeatherLayersBuilder old(b);
  old.add_layers(b.CreateVector(none));
  old.add_map_seed(9);
  old.add_ground_albedo(0.3);
  const auto body = old.Finish().Union();
  wire::FinishEnvelopeBuffer(b, wire::CreateEnvelope(b, 4, wire::Body::WeatherLayers, body));
  const DecodeResult r = decode(std::vector<std::uint8_t>(b.GetBufferPointer(), b.GetBufferPointer() + b.GetSize()));
  ASSERT_TRUE(r.ok()) << r.error_text;
  const WeatherLayers& o = std::get<WeatherLayers>(*r.message);
  EXPECT_EQ(o.map_seed, 9u);
  EXPECT_EQ(o.ground_albedo, 0.3);
  EXPECT_FALSE(o.visibility_m.has_value());
}

TEST(ProtocolCodec, DoublesSurviveBitExactly) {
  Pose p = sample_pose();
  p.lat_deg = std::nextafter(90.0, 0.0);
  p.lon_deg = -std::numeric_limits<double>::denorm_min();
  p.alt_m = 0.1 + 0.2;
  const DecodeResult r = round(p);
  ASSERT_TRUE(r.ok()) << r.error_text;
  const Pose& q = std::get<Pose>(*r.message);
  EXPECT_EQ(std::memcmp(&q.lat_deg, &p.lat_deg, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&q.lon_deg, &p.lon_deg, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&q.alt_m, &p.alt_m, sizeof(double)), 0);
}

TEST(ProtocolCodec, DecodesFromUnalignedMemory) {
  const std::vector<std::uint8_t> bytes = encode(sample_frame_ready(), 9);
  std::vector<std::uint8_t> shifted(bytes.size() + 3);
  for (std::size_t offset = 1; offset <= 3; ++offset) {
    std::memcpy(shifted.data() + offset, bytes.data(), bytes.size());
    const DecodeResult r = decode(std::span(shifted.data() + offset, bytes.size()));
    ASSERT_TRUE(r.ok()) << r.error_text;
    EXPECT_EQ(std::get<FrameReady>(*r.message), sample_frame_ready());
  }
}

TEST(ProtocolCodec, PayloadStartsWithRootOffsetAndIdentifier) {
  const std::vector<std::uint8_t> bytes = encode(SetTime{1.0e9}, 1);
  ASSERT_GE(bytes.size(), 8u);
  EXPECT_EQ(std::string(bytes.begin() + 4, bytes.begin() + 8), "CSVP");
  EXPECT_EQ(bytes.size() % 8, 0u);
}

// ---- semantic validation ----------------------------------------------------------------

struct Case {
  std::string name;
  Message message;
  std::string expect;  // substring of the error text (the field name)
};

template <class T>
Message with(T base, const std::function<void(T&)>& edit) {
  edit(base);
  return base;
}

void expect_invalid(const Case& c) {
  SCOPED_TRACE(c.name);
  const auto problem = validate(c.message);
  ASSERT_TRUE(problem.has_value()) << "accepted";
  EXPECT_NE(problem->find(c.expect), std::string::npos) << *problem;
  EXPECT_EQ(problem->find('\n'), std::string::npos);
  const DecodeResult r = round(c.message, 11);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error, ErrorCode::InvalidField);
  EXPECT_EQ(r.error_text, *problem);
  EXPECT_EQ(r.seq, 11u);
  EXPECT_EQ(r.to_error(), (Error{ErrorCode::InvalidField, *problem, 11}));
}

void expect_valid(const std::string& name, const Message& m) {
  SCOPED_TRACE(name);
  EXPECT_EQ(validate(m), std::nullopt);
  const DecodeResult r = round(m);
  ASSERT_TRUE(r.ok()) << r.error_text;
  EXPECT_EQ(*r.message, m);
}

// Every floating-point field of every message, by name, with a setter.
struct FloatField {
  std::string name;
  std::function<Message(double)> make;
};

std::vector<FloatField> float_fields() {
  std::vector<FloatField> f;
  auto pose = [&](std::string name, double Pose::*field) {
    f.push_back({"Pose." + name, [=](double v) {
                   Pose p = sample_pose();
                   p.*field = v;
                   return Message(p);
                 }});
    f.push_back({"FrameReady.pose." + name, [=](double v) {
                   FrameReady fr = sample_frame_ready();
                   fr.pose.*field = v;
                   return Message(fr);
                 }});
  };
  pose("sim_time_s", &Pose::sim_time_s);
  pose("lat_deg", &Pose::lat_deg);
  pose("lon_deg", &Pose::lon_deg);
  pose("alt_m", &Pose::alt_m);
  pose("heading_deg", &Pose::heading_deg);
  pose("pitch_deg", &Pose::pitch_deg);
  pose("roll_deg", &Pose::roll_deg);
  f.push_back({"Pose.utc_unix_s", [](double v) {
                 Pose p = sample_pose();
                 p.utc_unix_s = v;
                 return Message(p);
               }});
  auto velocity = [&](std::string name, double VelocityEnu::*field) {
    f.push_back({"Pose.velocity_enu." + name, [=](double v) {
                   Pose p = sample_pose();
                   (*p.velocity_enu).*field = v;
                   return Message(p);
                 }});
  };
  velocity("east_mps", &VelocityEnu::east_mps);
  velocity("north_mps", &VelocityEnu::north_mps);
  velocity("up_mps", &VelocityEnu::up_mps);
  f.push_back({"SetView.hfov_deg", [](double v) {
                 SetView s;
                 s.hfov_deg = v;
                 return Message(s);
               }});
  f.push_back({"SetTime.utc_unix_s", [](double v) { return Message(SetTime{v}); }});
  auto layer = [&](std::string name, double CloudLayer::*field) {
    f.push_back({"WeatherLayers.layers[1]." + name, [=](double v) {
                   WeatherLayers w = sample_layers();
                   w.layers[1].*field = v;
                   return Message(w);
                 }});
  };
  f.push_back({"WeatherLayers.ground_albedo", [](double v) {
                 WeatherLayers w = sample_layers();
                 w.ground_albedo = v;
                 return Message(w);
               }});
  f.push_back({"WeatherLayers.visibility_m", [](double v) {
                 WeatherLayers w = sample_layers();
                 w.visibility_m = v;
                 return Message(w);
               }});
  layer("base_m", &CloudLayer::base_m);
  layer("top_m", &CloudLayer::top_m);
  layer("coverage", &CloudLayer::coverage);
  layer("density_scale", &CloudLayer::density_scale);
  layer("droplet_diameter_um", &CloudLayer::droplet_diameter_um);
  layer("wind_east_mps", &CloudLayer::wind_east_mps);
  layer("wind_north_mps", &CloudLayer::wind_north_mps);
  auto tile = [&](std::string name, double WeatherMapTile::*field) {
    f.push_back({"WeatherMapTile." + name, [=](double v) {
                   WeatherMapTile t = sample_tile();
                   t.*field = v;
                   return Message(t);
                 }});
  };
  tile("lat_min_deg", &WeatherMapTile::lat_min_deg);
  tile("lat_max_deg", &WeatherMapTile::lat_max_deg);
  tile("lon_min_deg", &WeatherMapTile::lon_min_deg);
  tile("lon_max_deg", &WeatherMapTile::lon_max_deg);
  tile("valid_at_utc_s", &WeatherMapTile::valid_at_utc_s);
  f.push_back({"WeatherMapTile.data[17]", [](double v) {
                 WeatherMapTile t = sample_tile();
                 t.data[17] = static_cast<float>(v);
                 return Message(t);
               }});
  auto frame = [&](std::string name, double FrameReady::*field) {
    f.push_back({"FrameReady." + name, [=](double v) {
                   FrameReady fr = sample_frame_ready();
                   fr.*field = v;
                   return Message(fr);
                 }});
  };
  frame("sim_time_s", &FrameReady::sim_time_s);
  frame("render_ms", &FrameReady::render_ms);
  frame("latency_ms", &FrameReady::latency_ms);
  f.push_back({"Stats.fps", [](double v) {
                 Stats s{1, 30.0, 2, 1, 1};
                 s.fps = v;
                 return Message(s);
               }});
  return f;
}

TEST(ProtocolValidate, RejectsNaNAndInfinityInEveryFloatField) {
  const auto fields = float_fields();
  // Pose 8 + velocity 3, FrameReady.pose 7 + FrameReady 3, SetView 1, SetTime 1,
  // WeatherLayers.ground_albedo and visibility_m 2, CloudLayer 7, WeatherMapTile 5 + data,
  // Stats 1.
  EXPECT_EQ(fields.size(), 39u);
  for (const FloatField& field : fields) {
    for (const double bad : {kNaN, -kNaN, kInf, -kInf}) {
      // Wind and velocity name the component; data names the element index.
      expect_invalid({field.name + " = " + std::to_string(bad), field.make(bad), field.name});
    }
  }
}

TEST(ProtocolValidate, NaNTextSaysMustBeFinite) {
  Pose p = sample_pose();
  p.alt_m = kNaN;
  EXPECT_EQ(validate(p), "Pose.alt_m is nan (must be finite)");
  p = sample_pose();
  p.lat_deg = 91.0;
  EXPECT_EQ(validate(p), "Pose.lat_deg 91 out of range [-90, 90]");
}

TEST(ProtocolValidate, PoseRanges) {
  auto pose = [](const std::function<void(Pose&)>& edit) {
    return with<Pose>(sample_pose(), edit);
  };
  expect_invalid({"lat high", pose([](Pose& p) { p.lat_deg = 90.000001; }), "Pose.lat_deg"});
  expect_invalid({"lat low", pose([](Pose& p) { p.lat_deg = -90.000001; }), "Pose.lat_deg"});
  expect_invalid({"lon high", pose([](Pose& p) { p.lon_deg = 180.000001; }), "Pose.lon_deg"});
  expect_invalid({"lon low", pose([](Pose& p) { p.lon_deg = -180.000001; }), "Pose.lon_deg"});
  expect_invalid({"alt low", pose([](Pose& p) { p.alt_m = -500.01; }), "Pose.alt_m"});
  expect_invalid({"alt high", pose([](Pose& p) { p.alt_m = 100000.01; }), "Pose.alt_m"});
  expect_invalid({"heading", pose([](Pose& p) { p.heading_deg = 360.5; }), "Pose.heading_deg"});
  expect_invalid({"pitch", pose([](Pose& p) { p.pitch_deg = -90.5; }), "Pose.pitch_deg"});
  expect_invalid({"roll", pose([](Pose& p) { p.roll_deg = 180.5; }), "Pose.roll_deg"});
  expect_invalid(
      {"utc before 1900", pose([](Pose& p) { p.utc_unix_s = -2208988801.0; }), "Pose.utc_unix_s"});
  expect_invalid({"utc 2200", pose([](Pose& p) { p.utc_unix_s = kMaxUtc_s; }), "Pose.utc_unix_s"});
  expect_invalid({"speed", pose([](Pose& p) {
                    p.velocity_enu = VelocityEnu{8000, 6000, 1};
                  }),
                  "Pose.velocity_enu speed"});
  expect_invalid({"huge speed", pose([](Pose& p) {
                    p.velocity_enu = VelocityEnu{1e300, 1e300, 0};
                  }),
                  "Pose.velocity_enu speed"});
  expect_invalid({"flags", pose([](Pose& p) { p.flags = 0x04; }), "Pose.flags"});
  expect_invalid({"echo",
                  with<FrameReady>(sample_frame_ready(), [](FrameReady& f) { f.pose.alt_m = 2e5; }),
                  "FrameReady.pose.alt_m"});

  expect_valid("lat/lon/alt at their limits",
               pose([](Pose& p) { p.lat_deg = 90.0, p.lon_deg = -180.0, p.alt_m = -500.0; }));
  expect_valid("lon 180, alt 100 km", pose([](Pose& p) { p.lon_deg = 180.0, p.alt_m = 1e5; }));
  expect_valid("angles at their limits", pose([](Pose& p) {
                 p.heading_deg = -360.0, p.pitch_deg = 90.0, p.roll_deg = -180.0;
               }));
  expect_valid("speed exactly 10 km/s", pose([](Pose& p) {
                 p.velocity_enu = VelocityEnu{6000, 8000, 0};
               }));
  expect_valid("both flags", pose([](Pose& p) { p.flags = pose_flag::kAll; }));
  expect_valid("negative sim time", pose([](Pose& p) { p.sim_time_s = -5.0; }));
}

TEST(ProtocolValidate, ViewRanges) {
  auto view = [](const std::function<void(SetView&)>& edit) {
    return with<SetView>(SetView{}, edit);
  };
  expect_invalid({"width 0", view([](SetView& v) { v.width = 0; }), "SetView.width"});
  expect_invalid({"width 8193", view([](SetView& v) { v.width = 8193; }), "SetView.width"});
  expect_invalid({"height 0", view([](SetView& v) { v.height = 0; }), "SetView.height"});
  expect_invalid({"height 8193", view([](SetView& v) { v.height = 8193; }), "SetView.height"});
  expect_invalid({"fov 0", view([](SetView& v) { v.hfov_deg = 0.0; }), "SetView.hfov_deg"});
  expect_invalid(
      {"fov negative", view([](SetView& v) { v.hfov_deg = -10.0; }), "SetView.hfov_deg"});
  expect_invalid({"fov 170.01", view([](SetView& v) { v.hfov_deg = 170.01; }), "SetView.hfov_deg"});
  expect_invalid({"no sinks", view([](SetView& v) { v.sinks = 0; }), "SetView.sinks"});
  expect_invalid({"unknown sink", view([](SetView& v) { v.sinks = 0x09; }), "SetView.sinks"});
  expect_invalid({"shm format", view([](SetView& v) { v.shm_format = ShmPixelFormat{2}; }),
                  "SetView.shm_format"});
  expect_invalid({"file format", view([](SetView& v) { v.file_format = FileFormat{9}; }),
                  "SetView.file_format"});
  expect_invalid({"file sink without dir", view([](SetView& v) { v.sinks = sink::kFile; }),
                  "SetView.file_dir"});
  expect_invalid({"preset with space", view([](SetView& v) { v.quality_preset = "very high"; }),
                  "SetView.quality_preset"});
  expect_invalid({"preset too long", view([](SetView& v) { v.quality_preset.assign(65, 'a'); }),
                  "SetView.quality_preset"});
  expect_invalid(
      {"dir too long", view([](SetView& v) { v.file_dir.assign(4097, 'd'); }), "SetView.file_dir"});
  expect_invalid(
      {"dir with newline", view([](SetView& v) { v.file_dir = "/tmp\n/x"; }), "SetView.file_dir"});
  expect_valid("8192 x 1, fov 170",
               view([](SetView& v) { v.width = 8192, v.height = 1, v.hfov_deg = 170.0; }));
  expect_valid("all sinks", view([](SetView& v) {
                 v.sinks = sink::kAll, v.file_dir = "out", v.quality_preset = "ultra-2.5_x";
               }));
}

TEST(ProtocolValidate, TextFields) {
  expect_invalid({"bad UTF-8", Hello{1, 0, "host\xc3\x28", 0}, "Hello.client_name"});
  expect_invalid({"overlong UTF-8", Hello{1, 0, "\xc0\xaf", 0}, "Hello.client_name"});
  expect_invalid({"surrogate", Hello{1, 0, "\xed\xa0\x80", 0}, "Hello.client_name"});
  expect_invalid({"truncated UTF-8", Hello{1, 0, "ab\xe2\x82", 0}, "Hello.client_name"});
  expect_invalid({"NUL in name", Hello{1, 0, std::string("a\0b", 3), 0}, "Hello.client_name"});
  expect_invalid({"name too long", Hello{1, 0, std::string(257, 'n'), 0}, "Hello.client_name"});
  expect_invalid({"error text two lines", Error{ErrorCode::Internal, "a\nb", 1}, "Error.text"});
  expect_invalid(
      {"error text too long", Error{ErrorCode::Internal, std::string(1025, 'e'), 1}, "Error.text"});
  expect_invalid({"version too long",
                  with<Welcome>(Welcome{}, [](Welcome& w) { w.service_version.assign(65, 'v'); }),
                  "Welcome.service_version"});
  expect_invalid({"empty file path",
                  with<FrameReady>(sample_frame_ready(), [](FrameReady& f) { f.file_path = ""; }),
                  "FrameReady.file_path"});
  expect_valid("4-byte UTF-8 and 256 bytes",
               Hello{1, 0, "\xf0\x9f\x98\x80" + std::string(252, 'x'), 0});
  expect_valid("unknown error code from a newer minor", Error{ErrorCode{200}, "new", 0});
  expect_valid("unknown capability bits from a newer minor", Hello{1, 0, "", 0xffffffffu});
}

TEST(ProtocolValidate, LayerRanges) {
  auto layers = [](const std::function<void(WeatherLayers&)>& edit) {
    return with<WeatherLayers>(sample_layers(), edit);
  };
  expect_invalid(
      {"five layers", layers([](WeatherLayers& w) {
         w.layers.clear();
         for (int i = 0; i < 5; ++i) {
           w.layers.push_back(CloudLayer{7, 1000.0 * i, 1000.0 * i + 500.0, 0.5, 1, 20, 0, 0});
         }
       }),
       "WeatherLayers.layers has 5 layers"});
  expect_invalid(
      {"overlap", layers([](WeatherLayers& w) { w.layers[1].base_m = 1400.0; }),
       "WeatherLayers.layers[1].base_m 1400 below layers[0].top_m 1500 (layers overlap)"});
  expect_invalid({"unsorted", layers([](WeatherLayers& w) { std::swap(w.layers[0], w.layers[2]); }),
                  "(layers must be sorted by base_m)"});
  expect_invalid({"type 0", layers([](WeatherLayers& w) { w.layers[0].type = 0; }),
                  "WeatherLayers.layers[0].type"});
  expect_invalid({"type 11", layers([](WeatherLayers& w) { w.layers[2].type = 11; }),
                  "WeatherLayers.layers[2].type"});
  expect_invalid({"base below -500", layers([](WeatherLayers& w) { w.layers[0].base_m = -501; }),
                  "WeatherLayers.layers[0].base_m"});
  expect_invalid({"top above 20 km", layers([](WeatherLayers& w) { w.layers[2].top_m = 20001; }),
                  "WeatherLayers.layers[2].top_m"});
  expect_invalid({"top below base", layers([](WeatherLayers& w) { w.layers[0].top_m = 700; }),
                  "WeatherLayers.layers[0].top_m"});
  expect_invalid({"coverage channel 4", layers([](WeatherLayers& w) { w.layers[1].coverage_channel = 4; }),
                  "WeatherLayers.layers[1].coverage_channel 4 out of range [-1, 3]"});
  expect_invalid({"coverage channel -2", layers([](WeatherLayers& w) { w.layers[0].coverage_channel = -2; }),
                  "WeatherLayers.layers[0].coverage_channel -2 out of range [-1, 3]"});
  expect_invalid({"ground albedo 1.5", layers([](WeatherLayers& w) { w.ground_albedo = 1.5; }),
                  "WeatherLayers.ground_albedo 1.5 out of range [0, 1]"});
  expect_invalid({"ground albedo -0.2", layers([](WeatherLayers& w) { w.ground_albedo = -0.2; }),
                  "WeatherLayers.ground_albedo"});
  // Visibility, m: [weather::kMinVisibility_m, weather::kMaxVisibility_m]; below is fog.
  expect_invalid({"visibility 500 m", layers([](WeatherLayers& w) { w.visibility_m = 500.0; }),
                  "WeatherLayers.visibility_m 500 out of range [1000, 1e+06] m (below 1000 m is fog, not drawn)"});
  expect_invalid({"visibility 0 m", layers([](WeatherLayers& w) { w.visibility_m = 0.0; }),
                  "WeatherLayers.visibility_m 0 out of range"});
  expect_invalid({"visibility 2000 km", layers([](WeatherLayers& w) { w.visibility_m = 2.0e6; }),
                  "WeatherLayers.visibility_m 2e+06 out of range [1000, 1e+06]"});
  expect_invalid({"visibility just below", layers([](WeatherLayers& w) {
                    w.visibility_m = std::nextafter(weather::kMinVisibility_m, 0.0);
                  }),
                  "WeatherLayers.visibility_m"});
  expect_invalid({"visibility nan", layers([](WeatherLayers& w) { w.visibility_m = kNaN; }),
                  "WeatherLayers.visibility_m is nan (must be finite)"});
  expect_valid("visibility at the fog limit", layers([](WeatherLayers& w) { w.visibility_m = weather::kMinVisibility_m; }));
  expect_valid("visibility at the clear limit", layers([](WeatherLayers& w) { w.visibility_m = weather::kMaxVisibility_m; }));
  expect_invalid({"thickness 5 m", layers([](WeatherLayers& w) { w.layers[0].top_m = 805; }),
                  "WeatherLayers.layers[0].top_m"});
  expect_invalid({"coverage 1.01", layers([](WeatherLayers& w) { w.layers[0].coverage = 1.01; }),
                  "WeatherLayers.layers[0].coverage"});
  expect_invalid({"coverage -0.01", layers([](WeatherLayers& w) { w.layers[1].coverage = -0.01; }),
                  "WeatherLayers.layers[1].coverage"});
  expect_invalid({"density 10.5",
                  layers([](WeatherLayers& w) { w.layers[0].density_scale = 10.5; }),
                  "WeatherLayers.layers[0].density_scale"});
  expect_invalid({"droplet 4.9",
                  layers([](WeatherLayers& w) { w.layers[0].droplet_diameter_um = 4.9; }),
                  "WeatherLayers.layers[0].droplet_diameter_um"});
  expect_invalid({"droplet 50.1",
                  layers([](WeatherLayers& w) { w.layers[0].droplet_diameter_um = 50.1; }),
                  "WeatherLayers.layers[0].droplet_diameter_um"});
  expect_invalid({"wind 151", layers([](WeatherLayers& w) {
                    w.layers[0].wind_east_mps = 120, w.layers[0].wind_north_mps = 91;
                  }),
                  "WeatherLayers.layers[0].wind speed"});
  expect_valid("four touching layers at the limits", layers([](WeatherLayers& w) {
                 w.layers = {CloudLayer{10, -500, 1500, 0.0, 0.0, 5.0, 150, 0},
                             CloudLayer{9, 1500, 1510, 1.0, 10.0, 50.0, 0, -150},
                             CloudLayer{6, 1510, 12000, 0.5, 1, 20, 0, 0},
                             CloudLayer{1, 12000, 20000, 0.5, 1, 20, 0, 0}};
               }));
  expect_valid("no layers", WeatherLayers{});
}

TEST(ProtocolValidate, TileRanges) {
  auto tile = [](const std::function<void(WeatherMapTile&)>& edit) {
    return with<WeatherMapTile>(sample_tile(), edit);
  };
  expect_invalid({"one value short", tile([](WeatherMapTile& t) { t.data.pop_back(); }),
                  "WeatherMapTile.data has 29 values, expected 30"});
  expect_invalid({"one value extra", tile([](WeatherMapTile& t) { t.data.push_back(0.5f); }),
                  "WeatherMapTile.data has 31 values, expected 30"});
  expect_invalid({"channels mismatch",
                  tile([](WeatherMapTile& t) { t.channels = tile_channel::kAll; }), "expected 75"});
  expect_invalid(
      {"no channels", tile([](WeatherMapTile& t) { t.channels = 0; }), "WeatherMapTile.channels"});
  expect_invalid({"unknown channel", tile([](WeatherMapTile& t) { t.channels = 0x21; }),
                  "WeatherMapTile.channels"});
  expect_invalid({"width 0", tile([](WeatherMapTile& t) { t.width = 0, t.data.clear(); }),
                  "WeatherMapTile.width"});
  expect_invalid(
      {"width 1025", tile([](WeatherMapTile& t) { t.width = 1025; }), "WeatherMapTile.width"});
  expect_invalid({"height 0", tile([](WeatherMapTile& t) { t.height = 0, t.data.clear(); }),
                  "WeatherMapTile.height"});
  expect_invalid({"huge size does not overflow",
                  tile([](WeatherMapTile& t) { t.width = 0xffffffffu, t.height = 0xffffffffu; }),
                  "WeatherMapTile.width"});
  expect_invalid({"lat reversed", tile([](WeatherMapTile& t) { t.lat_max_deg = t.lat_min_deg; }),
                  "WeatherMapTile.lat_max_deg"});
  expect_invalid({"lat max 90.5", tile([](WeatherMapTile& t) { t.lat_max_deg = 90.5; }),
                  "WeatherMapTile.lat_max_deg"});
  expect_invalid({"lat min -91", tile([](WeatherMapTile& t) { t.lat_min_deg = -91; }),
                  "WeatherMapTile.lat_min_deg"});
  expect_invalid({"lon min 180",
                  tile([](WeatherMapTile& t) { t.lon_min_deg = 180, t.lon_max_deg = 190; }),
                  "WeatherMapTile.lon_min_deg"});
  expect_invalid({"lon min -180.5", tile([](WeatherMapTile& t) { t.lon_min_deg = -180.5; }),
                  "WeatherMapTile.lon_min_deg"});
  expect_invalid({"lon reversed", tile([](WeatherMapTile& t) { t.lon_max_deg = 160; }),
                  "WeatherMapTile.lon_max_deg"});
  expect_invalid({"lon span over 360", tile([](WeatherMapTile& t) { t.lon_max_deg = 530.001; }),
                  "WeatherMapTile.lon_max_deg"});
  expect_invalid({"value 1.5", tile([](WeatherMapTile& t) { t.data[7] = 1.5f; }),
                  "WeatherMapTile.data[7] 1.5 out of range [0, 1] (col 3, row 0, density)"});
  expect_invalid({"value -0.25", tile([](WeatherMapTile& t) { t.data[12] = -0.25f; }),
                  "(col 1, row 1, coverage)"});
  expect_invalid({"valid_at 2300", tile([](WeatherMapTile& t) { t.valid_at_utc_s = 1.05e10; }),
                  "WeatherMapTile.valid_at_utc_s"});
  expect_valid("whole world, antimeridian at the edge", tile([](WeatherMapTile& t) {
                 t.lat_min_deg = -90, t.lat_max_deg = 90, t.lon_min_deg = -180, t.lon_max_deg = 180;
               }));
  expect_valid("360 degrees starting at 170", tile([](WeatherMapTile& t) { t.lon_max_deg = 530; }));
  expect_valid("1024 x 1024 x 5", tile([](WeatherMapTile& t) {
                 t.width = t.height = 1024, t.channels = tile_channel::kAll;
                 t.data.assign(1024u * 1024u * 5u, 0.5f);
               }));
}

// One rule set for tiles (weather/map_tile.h): validate() says what MapTile::problem() says
// of the converted tile, in the message's field names; the protocol adds only its UTC range
// and sizes beyond what a MapTile holds. Exact texts, as a client sees them.
TEST(ProtocolValidate, TilesFollowTheWeatherModulesRules) {
  EXPECT_EQ(kMaxTileSize, static_cast<std::uint32_t>(weather::kMaxTileTexels));
  EXPECT_EQ(Welcome{}.limits.max_tile_size, kMaxTileSize);
  const std::vector<std::function<void(WeatherMapTile&)>> edits{
      [](WeatherMapTile& t) { t.lat_min_deg = -91; },
      [](WeatherMapTile& t) { t.lat_max_deg = kNaN; },
      [](WeatherMapTile& t) { t.lon_min_deg = 180, t.lon_max_deg = 190; },
      [](WeatherMapTile& t) { t.lon_max_deg = 530.001; },
      [](WeatherMapTile& t) { t.width = 1025; },
      [](WeatherMapTile& t) { t.height = 0; },
      [](WeatherMapTile& t) { t.channels = 0x30; },
      [](WeatherMapTile& t) { t.channels = 0; },
      [](WeatherMapTile& t) { t.valid_at_utc_s = -kInf; },
      [](WeatherMapTile& t) { t.data.pop_back(); },
      [](WeatherMapTile& t) { t.data[9] = -kNaN; },
  };
  for (std::size_t i = 0; i < edits.size(); ++i) {
    SCOPED_TRACE(i);
    WeatherMapTile t = sample_tile();
    edits[i](t);
    const std::string problem = to_map_tile(t).problem("WeatherMapTile.");
    EXPECT_FALSE(problem.empty());
    EXPECT_EQ(validate(t), problem);
  }
  auto tile = [](const std::function<void(WeatherMapTile&)>& edit) {
    return with<WeatherMapTile>(sample_tile(), edit);
  };
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.width = 1025; })), "WeatherMapTile.width 1025 out of range [1, 1024]");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.height = 0xffffffffu; })),
            "WeatherMapTile.height 4294967295 out of range [1, 1024]");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.channels = 0x21; })), "WeatherMapTile.channels has unknown bits 0x20");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.channels = 0; })),
            "WeatherMapTile.channels and layer_channels are empty");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.layer_channels = 0x30; })),
            "WeatherMapTile.layer_channels has unknown bits 0x30");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.lon_min_deg = -180.5; })),
            "WeatherMapTile.lon_min_deg -180.5 out of range [-180, 180)");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.lat_max_deg = 45; })),
            "WeatherMapTile.lat_max_deg 45 out of range (45, 90]");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.valid_at_utc_s = kNaN; })),
            "WeatherMapTile.valid_at_utc_s is nan (must be finite)");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.valid_at_utc_s = 1.05e10; })),
            "WeatherMapTile.valid_at_utc_s 1.05e+10 out of range [-2208988800, 7258118400)");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.data.push_back(0.5f); })),
            "WeatherMapTile.data has 31 values, expected 30 (width 5 x height 3 x 2 channels)");
  EXPECT_EQ(validate(tile([](WeatherMapTile& t) { t.data[12] = -0.25f; })),
            "WeatherMapTile.data[12] -0.25 out of range [0, 1] (col 1, row 1, coverage)");
}

TEST(ProtocolValidate, OtherMessages) {
  expect_invalid({"request id 0", RenderRequest{0}, "RenderRequest.request_id"});
  expect_invalid({"dropped > received", Stats{1, 30.0, 5, 6, 1}, "Stats.poses_dropped"});
  expect_invalid({"negative fps", Stats{1, -1.0, 5, 1, 1}, "Stats.fps"});
  expect_invalid({"negative frame time", Stats{1, 1.0, 5, 1, 1, -2.0}, "Stats.frame_in_progress_ms"});
  expect_invalid({"negative render time",
                  with<FrameReady>(sample_frame_ready(), [](FrameReady& f) { f.render_ms = -0.5; }),
                  "FrameReady.render_ms"});
  expect_invalid({"frame width 0",
                  with<FrameReady>(sample_frame_ready(), [](FrameReady& f) { f.width = 0; }),
                  "FrameReady.width"});
  expect_invalid({"zero limits", with<Welcome>(Welcome{}, [](Welcome& w) { w.limits = Limits{}; }),
                  "Welcome.limits.max_payload_bytes"});
  expect_invalid(
      {"limits above the protocol's",
       with<Welcome>(Welcome{}, [](Welcome& w) { w.limits.max_tile_size = kMaxTileSize + 1; }),
       "Welcome.limits.max_tile_size"});
  expect_invalid({"SetTime 2200", SetTime{kMaxUtc_s}, "SetTime.utc_unix_s"});
  expect_valid("SetTime 1900", SetTime{kMinUtc_s});
  expect_valid("smaller limits", with<Welcome>(Welcome{}, [](Welcome& w) {
                 w.limits = Limits{1 << 20, 4096, 2, 256};
               }));
}

// ---- raw envelopes the encoder never writes ---------------------------------------------

std::vector<std::uint8_t> finish(flatbuffers::FlatBufferBuilder& b,
                                 flatbuffers::Offset<wire::Envelope> env) {
  wire::FinishEnvelopeBuffer(b, env);
  return {b.GetBufferPointer(), b.GetBufferPointer() + b.GetSize()};
}

TEST(ProtocolDecode, RejectsEnvelopesTheEncoderNeverWrites) {
  {
    flatbuffers::FlatBufferBuilder b;
    const DecodeResult r = decode(finish(b, wire::CreateEnvelope(b, 5)));
    EXPECT_EQ(r.error, ErrorCode::UnknownMessage);
    EXPECT_EQ(r.seq, 5u);
    EXPECT_EQ(r.error_text, "Envelope.body is empty");
  }
  {
    flatbuffers::FlatBufferBuilder b;
    const auto body = wire::CreateSetTime(b, 1e9).Union();
    const DecodeResult r =
        decode(finish(b, wire::CreateEnvelope(b, 6, static_cast<wire::Body>(99), body)));
    EXPECT_EQ(r.error, ErrorCode::UnknownMessage);
    EXPECT_NE(r.error_text.find("type 99"), std::string::npos) << r.error_text;
  }
  {
    flatbuffers::FlatBufferBuilder b;
    const DecodeResult r = decode(finish(b, wire::CreateEnvelope(b, 7, wire::Body::Pose)));
    EXPECT_EQ(r.error, ErrorCode::Malformed);
    EXPECT_NE(r.error_text.find("Pose"), std::string::npos) << r.error_text;
  }
  {
    flatbuffers::FlatBufferBuilder b;
    const auto body = wire::CreateWelcome(b, 1, 0).Union();
    const DecodeResult r = decode(finish(b, wire::CreateEnvelope(b, 8, wire::Body::Welcome, body)));
    EXPECT_EQ(r.error, ErrorCode::InvalidField);
    EXPECT_EQ(r.error_text, "Welcome.limits is missing");
  }
  {
    flatbuffers::FlatBufferBuilder b;
    const auto body = wire::CreateFrameReady(b, 1, 0, 0, 0.0, flatbuffers::nullopt, 64, 64).Union();
    const DecodeResult r =
        decode(finish(b, wire::CreateEnvelope(b, 9, wire::Body::FrameReady, body)));
    EXPECT_EQ(r.error, ErrorCode::InvalidField);
    EXPECT_EQ(r.error_text, "FrameReady.pose is missing");
  }
  {
    const DecodeResult r = round(SetTime{1e9}, 0);
    EXPECT_EQ(r.error, ErrorCode::InvalidField);
    EXPECT_EQ(r.error_text, "Envelope.seq is 0 (must be >= 1)");
  }
  {
    std::vector<std::uint8_t> bytes = encode(SetTime{1e9}, 3);
    bytes[4] = 'X';  // file identifier
    const DecodeResult r = decode(bytes);
    EXPECT_EQ(r.error, ErrorCode::Malformed);
    EXPECT_NE(r.error_text.find("CSVP"), std::string::npos);
  }
}

TEST(ProtocolDecode, RejectsNaNWrittenStraightIntoTheBytes) {
  // A client in another language can put any bits in a double: find the latitude's bytes
  // in the payload and overwrite them with a NaN.
  const Pose pose = sample_pose();
  std::vector<std::uint8_t> bytes = encode(pose, 1);
  std::uint8_t lat[8];
  std::memcpy(lat, &pose.lat_deg, 8);
  const auto at = std::search(bytes.begin(), bytes.end(), lat, lat + 8);
  ASSERT_NE(at, bytes.end());
  const double nan = kNaN;
  std::memcpy(&*at, &nan, 8);
  const DecodeResult r = decode(bytes);
  EXPECT_EQ(r.error, ErrorCode::InvalidField);
  EXPECT_EQ(r.error_text, "Pose.lat_deg is nan (must be finite)");
}

TEST(ProtocolDecode, RejectsGarbageAndSizeExtremes) {
  EXPECT_EQ(decode({}).error, ErrorCode::Malformed);
  const std::vector<std::uint8_t> tiny = {1, 2, 3};
  EXPECT_EQ(decode(tiny).error, ErrorCode::Malformed);
  std::mt19937 rng(12345);
  for (int i = 0; i < 500; ++i) {
    std::vector<std::uint8_t> junk(rng() % 300);
    for (auto& b : junk) b = static_cast<std::uint8_t>(rng());
    if (junk.size() >= 8 && i % 2 == 0) std::memcpy(junk.data() + 4, "CSVP", 4);
    const DecodeResult r = decode(junk);
    EXPECT_FALSE(r.ok()) << "random bytes #" << i << " decoded as " << message_name(*r.message);
  }
}

// Truncation and mutation may leave a payload that still verifies (e.g. cutting trailing
// alignment padding, or flipping a bit of a value that stays in range). Whatever decode
// accepts must then be a valid message that survives another encode/decode unchanged.
void expect_sound(const DecodeResult& r) {
  if (!r.ok()) {
    EXPECT_NE(r.error, ErrorCode::Unspecified);
    EXPECT_FALSE(r.error_text.empty());
    return;
  }
  ASSERT_EQ(validate(*r.message), std::nullopt);
  const DecodeResult again = decode(encode(*r.message, r.seq));
  ASSERT_TRUE(again.ok()) << again.error_text;
  EXPECT_EQ(*again.message, *r.message);
}

TEST(ProtocolDecode, EveryTruncationIsRejectedOrHarmless) {
  for (const Message& m : sample_messages()) {
    SCOPED_TRACE(std::string(message_name(m)));
    const std::vector<std::uint8_t> bytes = encode(m, 3);
    int accepted = 0;
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      // A fresh exact-size copy, so that reading past n is a heap overflow under ASan.
      const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + n);
      const DecodeResult r = decode(cut);
      expect_sound(r);
      if (r.ok()) {
        ++accepted;
        EXPECT_EQ(*r.message, m) << "truncated to " << n << " of " << bytes.size();
      }
    }
    // Only trailing padding (< 8 bytes) may go unnoticed.
    EXPECT_LT(accepted, 8);
  }
}

TEST(ProtocolDecode, SeededRandomMutationsNeverCrashOrSmuggleInvalidValues) {
  const std::vector<Message> samples = sample_messages();
  std::vector<std::vector<std::uint8_t>> payloads;
  for (const Message& m : samples) payloads.push_back(encode(m, 77));
  std::mt19937_64 rng(20240611);
  const std::uint32_t interesting[] = {
      0,      1,          0x7f,       0x80,       0xff,
      0xffff, 0x7fffffff, 0x80000000, 0xffffffff, 0x7ff80000 /* NaN high word */};
  int accepted = 0, rejected = 0;
  constexpr int kIterations = 6000;
  for (int it = 0; it < kIterations; ++it) {
    std::vector<std::uint8_t> p = payloads[rng() % payloads.size()];
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits && !p.empty(); ++e) {
      const std::size_t at = rng() % p.size();
      switch (rng() % 6) {
        case 0:
          p[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
          break;
        case 1:
          p[at] = static_cast<std::uint8_t>(rng());
          break;
        case 2: {
          const std::uint32_t v = interesting[rng() % std::size(interesting)];
          const std::size_t pos = at & ~std::size_t{3};
          if (pos + 4 <= p.size()) std::memcpy(p.data() + pos, &v, 4);
          break;
        }
        case 3:
          p.insert(p.begin() + at, static_cast<std::uint8_t>(rng()));
          break;
        case 4:
          p.erase(p.begin() + at);
          break;
        default:
          p.resize(at);
          break;
      }
    }
    const DecodeResult r = decode(p);
    expect_sound(r);
    (r.ok() ? accepted : rejected)++;
    if (::testing::Test::HasFatalFailure()) {
      FAIL() << "iteration " << it;
    }
  }
  std::printf("mutations: %d accepted, %d rejected\n", accepted, rejected);
  // Both outcomes must occur, or the mutations test nothing.
  EXPECT_GT(accepted, kIterations / 50);
  EXPECT_GT(rejected, kIterations / 2);
}

// ---- docs/PROTOCOL.md stays true ------------------------------------------------------

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const std::filesystem::path kSourceRoot =
    std::filesystem::path(__FILE__).parent_path().parent_path();

TEST(ProtocolDocs, QuoteTheSchemaVerbatim) {
  const std::string doc = read_text(kSourceRoot / "docs/PROTOCOL.md");
  const std::string schema = read_text(kSourceRoot / "protocol/cloudsvc.fbs");
  ASSERT_FALSE(schema.empty());
  EXPECT_NE(doc.find("```\n" + schema + "```"), std::string::npos)
      << "docs/PROTOCOL.md must quote protocol/cloudsvc.fbs verbatim";
}

TEST(ProtocolDocs, HexExampleIsWhatTheEncoderWrites) {
  const std::vector<std::uint8_t> f = frame(encode(SetTime{1718000000.0}, 1));
  std::string hex;
  for (std::size_t i = 0; i < f.size(); ++i) {
    char b[4];
    std::snprintf(b, sizeof b, "%02x", f[i]);
    hex += b;
    hex += (i % 16 == 15 || i + 1 == f.size()) ? "\n" : " ";
  }
  const std::string doc = read_text(kSourceRoot / "docs/PROTOCOL.md");
  EXPECT_NE(doc.find("```\n" + hex + "```"), std::string::npos) << hex;
  EXPECT_EQ(f.size(), 72u);
}

}  // namespace
}  // namespace cloudsvc::protocol
