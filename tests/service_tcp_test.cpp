// `cloudsvc serve` end to end over TCP (tcp://127.0.0.1:<free port>, loopback only): the
// handshake, a short pose list replayed pose by pose (one frame per pose, frame numbers in
// order, every pose echoed in FrameReady and in the shared-memory slot), and a TCP client
// and a Unix-socket client of the same service both getting every FrameReady.
#include <gtest/gtest.h>

#include <vector>

#include "service_test_support.h"
#include "shm_frame_stats.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

// Pose i of a short climbing, turning track near Zurich (degrees, metres, seconds).
protocol::Pose track_pose(int i) {
  protocol::Pose p;
  p.sim_time_s = 100.0 + 0.5 * i;
  p.utc_unix_s = 1782043200.0 + 0.5 * i;  // 2026-06-21T12:00:00Z + 0.5 s per pose
  p.lat_deg = 47.45 + 0.0007 * i;
  p.lon_deg = 8.56 - 0.0003 * i;
  p.alt_m = 1500.0 + 25.0 * i;
  p.heading_deg = 80.0 + 3.0 * i;
  p.pitch_deg = 2.0 + 0.5 * i;
  p.roll_deg = -4.0 + i;
  p.velocity_enu = protocol::VelocityEnu{60.0, 10.0, 5.0};  // m/s
  if (i == 0) p.flags = protocol::pose_flag::kTeleport;
  return p;
}

void expect_echo(const protocol::Pose& sent, const protocol::FrameReady& r) {
  EXPECT_EQ(r.pose.lat_deg, sent.lat_deg);
  EXPECT_EQ(r.pose.lon_deg, sent.lon_deg);
  EXPECT_EQ(r.pose.alt_m, sent.alt_m);
  EXPECT_EQ(r.pose.heading_deg, sent.heading_deg);
  EXPECT_EQ(r.pose.pitch_deg, sent.pitch_deg);
  EXPECT_EQ(r.pose.roll_deg, sent.roll_deg);
  EXPECT_EQ(r.pose.sim_time_s, sent.sim_time_s);
  EXPECT_EQ(r.sim_time_s, sent.sim_time_s);
  EXPECT_EQ(r.pose.utc_unix_s, sent.utc_unix_s);
  EXPECT_EQ(r.pose.velocity_enu, sent.velocity_enu);
}

TEST(ServiceTcp, ReplayOfAShortPoseListGivesOneFramePerPoseInOrderWithEchoes) {
  ServiceProcess svc("tcp_replay", {}, ServiceProcess::Tcp::Yes);
  ASSERT_TRUE(svc.running()) << "port " << svc.tcp_port();
  ServiceConnection c(svc.tcp_address(), "tcp-replay");
  EXPECT_EQ(c.welcome().major, protocol::kProtocolMajor);
  const int n = 6;
  std::vector<std::uint64_t> numbers;
  for (int i = 0; i < n; ++i) {
    const protocol::Pose sent = track_pose(i);
    c.send(sent);
    const auto ready = c.receive_until<protocol::FrameReady>(60s);
    numbers.push_back(ready.frame_number);
    expect_echo(sent, ready);
    EXPECT_EQ(ready.request_id, 0u);
    EXPECT_EQ(ready.width, 64u);
    EXPECT_EQ(ready.height, 36u);
    ASSERT_TRUE(ready.shm_slot.has_value());
    ShmFrame f;
    ASSERT_TRUE(read_frame(svc.shm_name(), ready.frame_number, f));
    EXPECT_EQ(f.info.lat_deg, sent.lat_deg);
    EXPECT_EQ(f.info.lon_deg, sent.lon_deg);
    EXPECT_EQ(f.info.alt_m, sent.alt_m);
    EXPECT_EQ(f.info.roll_deg, sent.roll_deg);
    EXPECT_EQ(f.info.unix_time_s, *sent.utc_unix_s);
  }
  ASSERT_EQ(numbers.size(), static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) EXPECT_EQ(numbers[i], static_cast<std::uint64_t>(i + 1)) << "frame " << i;
  c.send(protocol::StatsRequest{});
  const auto stats = c.receive_until<protocol::Stats>(10s);
  EXPECT_EQ(stats.frames_rendered, static_cast<std::uint64_t>(n));
  EXPECT_EQ(stats.poses_received, static_cast<std::uint64_t>(n));
  EXPECT_EQ(stats.poses_dropped, 0u);
  EXPECT_EQ(svc.stop(), 0);
}

// Two handshaken clients, one per transport: the poses of either produce a FrameReady for
// both, with the same frame number and echo.
TEST(ServiceTcp, TcpAndUnixClientsBothReceiveEveryFrameReady) {
  ServiceProcess svc("tcp_two", {}, ServiceProcess::Tcp::Yes);
  ASSERT_TRUE(svc.running()) << "port " << svc.tcp_port();
  ServiceConnection tcp(svc.tcp_address(), "tcp-client");
  ServiceConnection unix_client(svc.address(), "unix-client");
  for (int i = 0; i < 4; ++i) {
    ServiceConnection& sender = i % 2 == 0 ? tcp : unix_client;
    const protocol::Pose sent = track_pose(i);
    sender.send(sent);
    const auto a = tcp.receive_until<protocol::FrameReady>(60s);
    const auto b = unix_client.receive_until<protocol::FrameReady>(60s);
    EXPECT_EQ(a.frame_number, static_cast<std::uint64_t>(i + 1));
    EXPECT_EQ(b.frame_number, a.frame_number);
    expect_echo(sent, a);
    expect_echo(sent, b);
  }
  tcp.send(protocol::StatsRequest{});
  EXPECT_EQ(tcp.receive_until<protocol::Stats>(10s).clients, 2u);
  EXPECT_EQ(svc.stop(), 0);
}

}  // namespace
}  // namespace cloudsvc::test
