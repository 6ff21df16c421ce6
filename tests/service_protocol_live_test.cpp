// Protocol corner cases against a running `cloudsvc serve` (docs/PROTOCOL.md): an unknown
// body type gets Error{UnknownMessage} and the connection goes on; a zero frame length is a
// fatal FramingError; a too-short frame length gets Malformed for the cut payload and then a
// FramingError for the rest; a connection beyond --max-clients gets Error{Busy} and is
// closed; SetTime moves the sun (mean radiance of the rendered frame).
#include <gtest/gtest.h>

#include "protocol/wire.h"
#include "raw_client.h"
#include "service_test_support.h"
#include "shm_frame_stats.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

// The test pose, looking 5 deg up.
protocol::Pose pose_at(double lat) {
  protocol::Pose p = test_pose(lat);
  p.pitch_deg = 5.0;
  return p;
}

// The next FrameReady for a pose at `lat` within 60 s (other messages skipped).
bool frame_for(RawClient& c, double lat) {
  for (int i = 0; i < 300; ++i) {
    auto m = c.receive(200ms);
    if (m && std::holds_alternative<protocol::FrameReady>(*m) && std::get<protocol::FrameReady>(*m).pose.lat_deg == lat)
      return true;
  }
  return false;
}

void expect_service_healthy(const ServiceProcess& svc, double lat) {
  ServiceConnection c(svc.address(), "healthy");
  c.send(pose_at(lat));
  EXPECT_EQ(c.receive_until<protocol::FrameReady>(60s).pose.lat_deg, lat);
}

class ServiceProtocolLive : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { svc_ = new ServiceProcess("proto_live"); }
  static void TearDownTestSuite() {
    EXPECT_EQ(svc_->stop(), 0);
    delete svc_;
  }
  static ServiceProcess* svc_;
};
ServiceProcess* ServiceProtocolLive::svc_ = nullptr;

TEST_F(ServiceProtocolLive, UnknownBodyTypeGetsUnknownMessageAndTheConnectionGoesOn) {
  ASSERT_TRUE(svc_->running());
  RawClient c(svc_->socket_path());
  handshake(c);
  flatbuffers::FlatBufferBuilder b;
  const auto body = wire::CreateSetTime(b, 1.78e9).Union();
  wire::FinishEnvelopeBuffer(b, wire::CreateEnvelope(b, 2, static_cast<wire::Body>(99), body));  // from a newer minor
  c.write(protocol::frame(std::vector<std::uint8_t>(b.GetBufferPointer(), b.GetBufferPointer() + b.GetSize())));
  const protocol::Error e = expect_error(c);
  EXPECT_EQ(e.code, protocol::ErrorCode::UnknownMessage);
  EXPECT_EQ(e.answers_seq, 2u);
  c.send(pose_at(21.0), 3);
  EXPECT_TRUE(frame_for(c, 21.0)) << "the connection did not go on after UnknownMessage";
  expect_service_healthy(*svc_, 22.0);
}

TEST_F(ServiceProtocolLive, ZeroFrameLengthIsAFramingErrorAndDisconnects) {
  RawClient c(svc_->socket_path());
  handshake(c);
  c.write({'C', 'S', 'V', '1', 0, 0, 0, 0});
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::FramingError);
  EXPECT_TRUE(c.closed_by_service(5s));
  expect_service_healthy(*svc_, 23.0);
}

// The header claims 4 bytes of a 60-odd-byte pose: those 4 do not verify (Malformed, not
// fatal), and the pose's remaining bytes read as the next header have no magic (fatal).
TEST_F(ServiceProtocolLive, TooShortFrameLengthGetsMalformedThenFramingError) {
  RawClient c(svc_->socket_path());
  handshake(c);
  auto bytes = protocol::frame(protocol::encode(pose_at(24.0), 2));
  ASSERT_GT(bytes.size(), 16u);
  bytes[4] = 4;
  bytes[5] = bytes[6] = bytes[7] = 0;
  c.write(bytes);
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::Malformed);
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::FramingError);
  EXPECT_TRUE(c.closed_by_service(5s));
  expect_service_healthy(*svc_, 25.0);
}

// SetTime alone (poses without utc_unix_s) sets the sun: the same view at local noon and
// at local 01:00 (sun well below the horizon in June at 47 N).
TEST_F(ServiceProtocolLive, SetTimeMovesTheSun) {
  ServiceConnection c(svc_->address(), "settime");
  auto luminance_at = [&](double utc_s) {
    c.send(protocol::SetTime{utc_s});
    protocol::Pose p = pose_at(47.45);
    p.flags = protocol::pose_flag::kTeleport;
    c.send(p);
    const auto ready = c.receive_until<protocol::FrameReady>(60s);
    EXPECT_FALSE(ready.pose.utc_unix_s.has_value());
    ShmFrame f;
    EXPECT_TRUE(read_frame(svc_->shm_name(), ready.frame_number, f));
    const FrameStats s = stats_of(f);
    EXPECT_EQ(s.nonfinite, 0u);
    EXPECT_EQ(f.info.unix_time_s, utc_s) << "the frame was not rendered for the SetTime";
    return s.mean_luminance;
  };
  const double noon = luminance_at(1782039600.0);   // 2026-06-21T11:00:00Z (13:00 local)
  const double night = luminance_at(1782082800.0);  // 2026-06-21T23:00:00Z (01:00 local)
  RecordProperty("mean_luminance_noon", std::to_string(noon));
  RecordProperty("mean_luminance_night", std::to_string(night));
  EXPECT_GT(noon, 0.0);
  EXPECT_LT(night, 0.01 * noon);
  EXPECT_GT(luminance_at(1782039600.0), 0.5 * noon) << "SetTime back to noon did not bring the sun back";
}

// --max-clients 2: a third connection is refused with Busy before any Hello and closed;
// once a client leaves, a new one is admitted.
TEST(ServiceMaxClients, ConnectionBeyondTheLimitGetsBusyAndIsClosed) {
  ServiceProcess svc("maxclients", {"--max-clients", "2"});
  ASSERT_TRUE(svc.running());
  auto a = std::make_unique<ServiceConnection>(svc.address(), "a");
  ServiceConnection b(svc.address(), "b");
  RawClient third(svc.socket_path());
  ASSERT_TRUE(third.connected());
  const protocol::Error e = expect_error(third);
  EXPECT_EQ(e.code, protocol::ErrorCode::Busy);
  EXPECT_NE(e.text.find("too many clients (2)"), std::string::npos) << e.text;
  EXPECT_TRUE(third.closed_by_service(5s));
  EXPECT_THROW(ServiceConnection(svc.address(), "fourth"), client::ConnectionError);

  b.send(pose_at(47.0));
  EXPECT_EQ(b.receive_until<protocol::FrameReady>(60s).pose.lat_deg, 47.0) << "the refusals disturbed a client";
  a.reset();  // a leaves; the service notices the EOF asynchronously
  std::unique_ptr<ServiceConnection> late;
  for (int i = 0; i < 50 && !late; ++i) {
    try {
      late = std::make_unique<ServiceConnection>(svc.address(), "late");
    } catch (const client::ConnectionError&) {
      std::this_thread::sleep_for(100ms);  // retry interval, not an assertion
    }
  }
  ASSERT_TRUE(late) << "no client admitted after one of two left";
  late->send(protocol::StatsRequest{});
  EXPECT_EQ(late->receive_until<protocol::Stats>(10s).clients, 2u);
  EXPECT_EQ(svc.stop(), 0);
}

}  // namespace
}  // namespace cloudsvc::test
