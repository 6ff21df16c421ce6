// Example protocol messages for the seed corpora (seed_messages.h).
#include "fuzz/seed_messages.h"

namespace cloudsvc::fuzz {

using namespace cloudsvc::protocol;

namespace {

Pose example_pose() {
  Pose p;
  p.sim_time_s = 12.5;
  p.utc_unix_s = 1782043200.0;  // 2026-06-21T12:00:00Z
  p.lat_deg = 47.45;
  p.lon_deg = 8.56;
  p.alt_m = 2500.0;
  p.heading_deg = 270.0;
  p.pitch_deg = 5.0;
  p.roll_deg = -10.0;
  p.velocity_enu = VelocityEnu{-120.0, 3.0, 1.5};
  p.flags = pose_flag::kTeleport;
  return p;
}

CloudLayer layer(std::uint8_t type, double base_m, double top_m, double coverage) {
  CloudLayer l;
  l.type = type;
  l.base_m = base_m;
  l.top_m = top_m;
  l.coverage = coverage;
  l.wind_east_mps = 8.0;
  l.wind_north_mps = -3.0;
  return l;
}

// 3 x 2 texels of coverage and density, valid at the example pose's time.
WeatherMapTile example_tile() {
  WeatherMapTile t;
  t.lat_min_deg = 45.0;
  t.lat_max_deg = 48.0;
  t.lon_min_deg = 175.0;
  t.lon_max_deg = 185.0;  // across the antimeridian
  t.width = 3;
  t.height = 2;
  t.channels = tile_channel::kCoverage | tile_channel::kDensity;
  t.valid_at_utc_s = 1782043200.0;
  t.data = {0.0f, 0.5f, 0.25f, 1.0f, 0.75f, 0.5f, 1.0f, 0.0f, 0.5f, 0.5f, 0.125f, 0.875f};
  return t;
}

}  // namespace

std::vector<std::pair<std::string, Message>> valid_seed_messages() {
  Welcome welcome;
  welcome.service_version = "0.1.0";
  welcome.capabilities = capability::kAll;
  SetView view;
  view.width = 640;
  view.height = 360;
  view.sinks = sink::kShm | sink::kFile;
  view.shm_format = ShmPixelFormat::Rgba8Srgb;
  view.file_dir = "frames";
  view.quality_preset = "default";
  WeatherLayers layers;
  layers.layers = {layer(7, 1200.0, 2400.0, 0.4), layer(2, 5000.0, 6500.0, 0.8)};
  layers.map_seed = 42;
  FrameReady ready;
  ready.frame_number = 3;
  ready.request_id = 7;
  ready.pose = example_pose();
  ready.sim_time_s = ready.pose.sim_time_s;
  ready.shm_slot = 1;
  ready.width = 640;
  ready.height = 360;
  ready.render_ms = 41.5;
  ready.latency_ms = 60.25;
  ready.file_path = "frames/frame-000003.png";
  Stats stats;
  stats.frames_rendered = 100;
  stats.fps = 24.5;
  stats.poses_received = 120;
  stats.poses_dropped = 20;
  stats.clients = 2;
  return {
      {"hello", Hello{kProtocolMajor, kProtocolMinor, "fuzz seed", capability::kAll}},
      {"welcome", welcome},
      {"set-view", view},
      {"pose", example_pose()},
      {"set-time", SetTime{1782043200.0}},
      {"weather-layers", layers},
      {"weather-map-tile", example_tile()},
      {"render-request", RenderRequest{7}},
      {"frame-ready", ready},
      {"error", Error{ErrorCode::InvalidField, "Pose.lat_deg 91 out of range [-90, 90]", 5}},
      {"stats-request", StatsRequest{}},
      {"stats", stats},
  };
}

std::vector<std::pair<std::string, Message>> invalid_seed_messages() {
  Pose pole = example_pose();
  pole.lat_deg = 91.0;
  WeatherLayers overlap;
  overlap.layers = {layer(7, 1200.0, 2400.0, 0.4), layer(9, 2000.0, 3000.0, 0.6)};
  WeatherMapTile short_tile = example_tile();
  short_tile.data.pop_back();
  return {
      {"pose-lat-91", pole},
      {"layers-overlap", overlap},
      {"tile-short-data", short_tile},
      {"hello-major-2", Hello{2, 0, "future client", 0}},
  };
}

}  // namespace cloudsvc::fuzz
