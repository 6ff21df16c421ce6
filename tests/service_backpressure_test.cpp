// Clients that do not read, against a running `cloudsvc serve`: a handshaken client whose
// socket is full does not stall rendering or replies for another client and loses none of
// its queued replies below the bound; a client that floods requests but never reads the
// replies is disconnected once its outbound queue passes the documented 4 MiB
// (docs/PROTOCOL.md, "Limits"), and the others are unaffected.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/time.h>

#include <cerrno>
#include <fstream>
#include <sstream>

#include "raw_client.h"
#include "service_test_support.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

// The stalled client asks for 5000 Stats (about 0.4 MB of replies: far more than a Unix
// socket buffers, far less than the 1 MiB notice bound) and reads nothing while another
// client replays 8 poses lock-step. Then it reads: every reply is there, in order.
TEST(ServiceBackpressure, StalledReaderDoesNotStallRenderingForAnotherClient) {
  ServiceProcess svc("stalled");
  ASSERT_TRUE(svc.running());
  RawClient stalled(svc.socket_path());
  handshake(stalled);
  const int requests = 5000;
  std::vector<std::uint8_t> burst;
  for (int i = 0; i < requests; ++i) {
    const auto f = protocol::frame(protocol::encode(protocol::StatsRequest{}, 2 + static_cast<std::uint64_t>(i)));
    burst.insert(burst.end(), f.begin(), f.end());
  }
  stalled.write(burst);

  ServiceConnection driver(svc.address(), "driver");
  const int poses = 8;
  for (int i = 0; i < poses; ++i) {
    driver.send(test_pose(47.0 + 0.001 * i, i));
    const auto ready = driver.receive_until<protocol::FrameReady>(60s);
    EXPECT_EQ(ready.frame_number, static_cast<std::uint64_t>(i + 1));
    EXPECT_EQ(ready.pose.lat_deg, 47.0 + 0.001 * i);
  }
  driver.send(protocol::StatsRequest{});
  const auto s = driver.receive_until<protocol::Stats>(10s);
  EXPECT_EQ(s.clients, 2u) << "the stalled client was disconnected below the bound";
  EXPECT_EQ(s.frames_rendered, static_cast<std::uint64_t>(poses));

  // The stalled client now reads its backlog: all Stats answers, and the FrameReady notices
  // of the frames rendered meanwhile (interleaved after the Stats sent before them).
  int stats = 0, frames = 0;
  while (stats < requests || frames < poses) {
    auto m = stalled.receive(10s);
    ASSERT_TRUE(m.has_value()) << "backlog ended after " << stats << " Stats and " << frames << " FrameReady";
    if (std::holds_alternative<protocol::Stats>(*m)) ++stats;
    else if (std::holds_alternative<protocol::FrameReady>(*m)) ++frames;
    else FAIL() << "unexpected " << protocol::message_name(*m);
  }
  EXPECT_EQ(stats, requests);
  EXPECT_EQ(frames, poses);
  EXPECT_EQ(svc.stop(), 0);
}

// Undecodable payloads (12 junk bytes each, 20 bytes framed) each get a Malformed Error of
// several times that size; the client never reads. The service must hang up on it within a
// bounded amount of input (the 4 MiB queue plus socket buffers is reached after ~1 MB of
// junk; 64 MiB is the give-up bound), log why, and keep serving another client.
TEST(ServiceBackpressure, ClientFloodingBadMessagesWithoutReadingIsDisconnected) {
  ServiceProcess svc("flooder");
  ASSERT_TRUE(svc.running());
  RawClient flooder(svc.socket_path());
  handshake(flooder);
  const timeval send_timeout{10, 0};  // a service that stops reading would block us: fail instead of hanging
  ASSERT_EQ(::setsockopt(flooder.fd(), SOL_SOCKET, SO_SNDTIMEO, &send_timeout, sizeof send_timeout), 0);
  const std::vector<std::uint8_t> junk = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const auto one = protocol::frame(junk);
  std::vector<std::uint8_t> batch;
  for (int i = 0; i < 1000; ++i) batch.insert(batch.end(), one.begin(), one.end());
  std::size_t written = 0;
  int err = 0;
  while (written < (64u << 20)) {
    if (!flooder.try_write(batch)) {
      err = errno;
      break;
    }
    written += batch.size();
  }
  EXPECT_TRUE(err == EPIPE || err == ECONNRESET) << "after " << written << " bytes: errno " << err << " ("
                                                 << std::strerror(err) << "), expected a disconnect";
  EXPECT_LT(written, 16u << 20) << "the queue bound was not applied";
  RecordProperty("junk_bytes_written", std::to_string(written));
  EXPECT_NE(read_text_file(svc.log_path()).find("bytes of replies queued (it does not read)"), std::string::npos);

  ServiceConnection other(svc.address(), "other");
  other.send(test_pose(47.5, 1.0));
  EXPECT_EQ(other.receive_until<protocol::FrameReady>(60s).pose.lat_deg, 47.5);
  other.send(protocol::StatsRequest{});
  EXPECT_EQ(other.receive_until<protocol::Stats>(10s).clients, 1u);
  EXPECT_EQ(svc.stop(), 0);
}

}  // namespace
}  // namespace cloudsvc::test
