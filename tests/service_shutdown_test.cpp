// Shutdown of `cloudsvc serve` by signal: SIGINT and SIGTERM (the latter while a TCP client
// streams poses, so a frame is being rendered when it arrives) both end the process with
// exit code 0, close the client's connection, and remove the Unix socket file and the
// shared-memory segment; the TCP port stops accepting.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "raw_client.h"
#include "service_test_support.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

// The i-th pose of a slow northward track (1e-4 deg and 0.1 s apart).
protocol::Pose pose_at(int i) { return test_pose(47.45 + 1e-4 * i, 0.1 * i); }

void expect_cleaned_up(const ServiceProcess& svc) {
  EXPECT_FALSE(std::filesystem::exists(svc.socket_path())) << "socket file left behind";
  EXPECT_FALSE(std::filesystem::exists("/dev/shm/" + svc.shm_name())) << "shared memory left behind";
  RawClient late(svc.tcp_port());
  EXPECT_FALSE(late.connected()) << "TCP port still accepting";
}

TEST(ServiceShutdown, SigintExitsZeroAndRemovesSocketAndSharedMemory) {
  ServiceProcess svc("sigint", {}, ServiceProcess::Tcp::Yes);
  ASSERT_TRUE(svc.running());
  {
    ServiceConnection c(svc.tcp_address(), "sigint");
    c.send(pose_at(0));
    c.receive_until<protocol::FrameReady>(60s);
  }
  ASSERT_TRUE(std::filesystem::exists("/dev/shm/" + svc.shm_name()));
  EXPECT_EQ(svc.stop(SIGINT), 0);
  expect_cleaned_up(svc);
  const std::string log = read_text_file(svc.log_path());
  EXPECT_NE(log.find("signal 2"), std::string::npos) << log;
  EXPECT_NE(log.find("stopped after 1 frames"), std::string::npos) << log;
}

// The client keeps a pose pending at all times (latest wins: the service renders back to
// back), SIGTERM arrives after the first frame; the client keeps sending until the service
// closes its connection.
TEST(ServiceShutdown, SigtermWithAClientStreamingPosesExitsZeroAndCleansUp) {
  ServiceProcess svc("sigterm_busy", {}, ServiceProcess::Tcp::Yes);
  ASSERT_TRUE(svc.running());
  RawClient c(svc.tcp_port());
  handshake(c);
  std::uint64_t seq = 2;
  int i = 0;
  c.send(pose_at(i++), seq++);
  bool got_frame = false, closed = false;
  for (int k = 0; k < 300 && !got_frame && !closed; ++k) {
    auto m = c.receive(200ms, &closed);
    got_frame = m && std::holds_alternative<protocol::FrameReady>(*m);
  }
  ASSERT_TRUE(got_frame);
  for (int k = 0; k < 3; ++k) c.send(pose_at(i++), seq++);  // frames in flight
  svc.signal(SIGTERM);
  int frames_after_signal = 0;
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (!closed && std::chrono::steady_clock::now() < deadline) {
    c.try_write(protocol::frame(protocol::encode(pose_at(i++), seq++)));  // fails once the service is gone
    auto m = c.receive(20ms, &closed);
    if (m && std::holds_alternative<protocol::FrameReady>(*m)) ++frames_after_signal;
  }
  EXPECT_TRUE(closed) << "the service did not close the client's connection";
  EXPECT_EQ(svc.wait_exit(30s), 0);
  expect_cleaned_up(svc);
  const std::string log = read_text_file(svc.log_path());
  EXPECT_NE(log.find("signal 15"), std::string::npos) << log;
  RecordProperty("poses_sent", std::to_string(i));
  RecordProperty("frames_after_signal", std::to_string(frames_after_signal));
}

}  // namespace
}  // namespace cloudsvc::test
