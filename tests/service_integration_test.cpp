// `cloudsvc serve` end to end over a Unix socket: handshake, pose -> frame (numbers, pose
// echo, shared memory), latest-wins under a flood, replay of a short log, and shutdown.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "protocol/shm/shm_frame_reader.h"
#include "service_test_support.h"
#include "sim_client/flight_log.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

protocol::Pose make_pose(double sim_t, double lat, double lon, double alt, double heading) {
  protocol::Pose p;
  p.sim_time_s = sim_t;
  p.lat_deg = lat;
  p.lon_deg = lon;
  p.alt_m = alt;
  p.heading_deg = heading;
  p.pitch_deg = 5.0;
  return p;
}

TEST(Service, PoseGivesFrameWithEchoInSharedMemory) {
  ServiceProcess svc("echo");
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "test");
  EXPECT_EQ(c.welcome().major, protocol::kProtocolMajor);
  EXPECT_TRUE(c.welcome().capabilities & protocol::capability::kSinkShm);
  c.send(make_pose(10.0, 47.45, 8.56, 1500.0, 90.0));
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  EXPECT_EQ(ready.frame_number, 1u);
  EXPECT_EQ(ready.pose.lat_deg, 47.45);
  EXPECT_EQ(ready.width, 64u);
  EXPECT_EQ(ready.height, 36u);
  ASSERT_TRUE(ready.shm_slot.has_value());
  EXPECT_GE(ready.latency_ms, ready.render_ms);

  ShmFrameReader reader(svc.shm_name());
  ShmFrame f;
  ASSERT_TRUE(reader.read_latest(0, f));
  EXPECT_EQ(f.info.frame_number, 1u);
  EXPECT_EQ(f.info.lat_deg, 47.45);
  EXPECT_EQ(f.info.heading_deg, 90.0);
  EXPECT_EQ(f.info.width, 64u);
  EXPECT_EQ(f.info.pixel_format, CLOUDSVC_SHM_RGBA16F_LINEAR);
  EXPECT_EQ(f.pixels.size(), 64u * 36u * 8u);
  EXPECT_EQ(svc.stop(), 0);
}

// A short log replayed pose by pose (waiting for each frame): one frame per pose, frame
// numbers 1..n in order, every echo equal to the pose sent.
TEST(Service, ReplayOfAShortLogGivesOneFramePerPoseInOrder) {
  ServiceProcess svc("replay");
  ASSERT_TRUE(svc.running());
  const auto csv = svc.dir() / "log.csv";
  {
    std::ofstream f(csv);
    f << "time,lat,lon,alt,heading,pitch,roll\n";
    for (int i = 0; i < 6; ++i)
      f << "2026-06-21T12:00:0" << i << "Z," << 47.45 + 0.001 * i << ",8.56," << 1500 + 10 * i << ",90,2,0\n";
  }
  const sim::PoseTrack track = sim::load_flight_log(csv.string());
  ASSERT_EQ(track.samples.size(), 6u);
  ServiceConnection c(svc.address(), "replay-test");
  std::uint64_t expect_frame = 1;
  for (const sim::PoseSample& s : track.samples) {
    protocol::Pose p = make_pose(s.unix_time_s, s.position.lat_deg, s.position.lon_deg, s.position.alt_m,
                                 s.attitude.heading_deg);
    p.utc_unix_s = s.unix_time_s;
    c.send(p);
    const auto ready = c.receive_until<protocol::FrameReady>(60s);
    EXPECT_EQ(ready.frame_number, expect_frame++);
    EXPECT_EQ(ready.pose.lat_deg, s.position.lat_deg);
    EXPECT_EQ(ready.pose.alt_m, s.position.alt_m);
    EXPECT_EQ(ready.sim_time_s, s.unix_time_s);
  }
  EXPECT_EQ(svc.stop(), 0);
}

// 300 poses sent without waiting: the service renders only the newest ones (latest wins),
// counts the rest as dropped, and the last frame shows the last pose.
TEST(Service, FloodOfPosesIsLatestWins) {
  ServiceProcess svc("flood");
  ASSERT_TRUE(svc.running());
  ServiceConnection c(svc.address(), "flood");
  const int n = 300;
  for (int i = 0; i < n; ++i) c.send(make_pose(i, 47.0 + i * 1e-4, 8.0, 1000.0, 0.0));
  const double last_lat = 47.0 + (n - 1) * 1e-4;
  protocol::FrameReady last{};
  int frames = 0;
  while (last.pose.lat_deg != last_lat) {
    last = c.receive_until<protocol::FrameReady>(60s);
    ++frames;
  }
  EXPECT_LT(frames, n / 2) << "a backlog was rendered";
  c.send(protocol::StatsRequest{});
  const auto stats = c.receive_until<protocol::Stats>(10s);
  EXPECT_EQ(stats.poses_received, static_cast<std::uint64_t>(n));
  EXPECT_GT(stats.poses_dropped, static_cast<std::uint64_t>(n / 2));
  EXPECT_EQ(stats.frames_rendered, static_cast<std::uint64_t>(frames));
  EXPECT_EQ(svc.stop(), 0);
}

TEST(Service, SigtermRemovesSocketAndSharedMemoryAndExitsZero) {
  ServiceProcess svc("term");
  ASSERT_TRUE(svc.running());
  {
    ServiceConnection c(svc.address(), "term");
    c.send(make_pose(1.0, 47.45, 8.56, 1500.0, 90.0));
    c.receive_until<protocol::FrameReady>(60s);
  }
  EXPECT_TRUE(std::filesystem::exists("/dev/shm/" + svc.shm_name()));
  EXPECT_EQ(svc.stop(SIGTERM), 0);
  EXPECT_FALSE(std::filesystem::exists(svc.socket_path()));
  EXPECT_FALSE(std::filesystem::exists("/dev/shm/" + svc.shm_name()));
}

}  // namespace
}  // namespace cloudsvc::test
