// Bad input and faults against a running `cloudsvc serve`: each gets an Error or a
// disconnect of that client only; the service keeps rendering for the others and its
// state is what it was before the bad message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "raw_client.h"
#include "service_test_support.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::test {
namespace {

using namespace std::chrono_literals;
using client::ServiceConnection;

// The service still renders for a well-behaved client.
void expect_service_healthy(const ServiceProcess& svc, double lat) {
  ServiceConnection c(svc.address(), "healthy");
  c.send(test_pose(lat));
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  EXPECT_EQ(ready.pose.lat_deg, lat);
}

RawClient handshaken(const ServiceProcess& svc) {
  RawClient c(svc.socket_path());
  handshake(c);
  return c;
}

class ServiceFaults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { svc_ = new ServiceProcess("faults"); }
  static void TearDownTestSuite() {
    EXPECT_EQ(svc_->stop(), 0);
    delete svc_;
  }
  static ServiceProcess* svc_;
};
ServiceProcess* ServiceFaults::svc_ = nullptr;

TEST_F(ServiceFaults, ClientKilledMidMessageAffectsNobodyElse) {
  ASSERT_TRUE(svc_->running());
  {
    RawClient c = handshaken(*svc_);
    auto bytes = protocol::frame(protocol::encode(test_pose(10.0), 2));
    bytes.resize(bytes.size() / 2);  // truncated frame, then the client vanishes
    c.write(bytes);
  }
  expect_service_healthy(*svc_, 11.0);
}

TEST_F(ServiceFaults, OversizeLengthIsAFramingErrorAndDisconnects) {
  RawClient c = handshaken(*svc_);
  std::vector<std::uint8_t> header = {'C', 'S', 'V', '1', 0xff, 0xff, 0xff, 0x7f};
  c.write(header);
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::FramingError);
  EXPECT_TRUE(c.closed_by_service(5s));
  expect_service_healthy(*svc_, 12.0);
}

TEST_F(ServiceFaults, BadMagicIsAFramingErrorAndDisconnects) {
  RawClient c = handshaken(*svc_);
  c.write({'G', 'E', 'T', ' ', '/', ' ', 'H', 'T'});
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::FramingError);
  EXPECT_TRUE(c.closed_by_service(5s));
}

TEST_F(ServiceFaults, GarbagePayloadGetsErrorAndTheConnectionLives) {
  RawClient c = handshaken(*svc_);
  const std::vector<std::uint8_t> junk = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  c.write(protocol::frame(junk));
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::Malformed);
  c.send(test_pose(13.0), 3);
  bool got = false;
  for (int i = 0; i < 300 && !got; ++i) {
    auto m = c.receive(200ms);
    got = m && std::holds_alternative<protocol::FrameReady>(*m) && std::get<protocol::FrameReady>(*m).pose.lat_deg == 13.0;
  }
  EXPECT_TRUE(got);
}

TEST_F(ServiceFaults, WrongProtocolVersionIsRefused) {
  RawClient c(svc_->socket_path());
  protocol::Hello h;
  h.major = 99;
  c.send(h, 1);
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::VersionMismatch);
  EXPECT_TRUE(c.closed_by_service(5s));
}

TEST_F(ServiceFaults, MessageBeforeHelloIsRefused) {
  RawClient c(svc_->socket_path());
  c.send(test_pose(14.0), 1);
  EXPECT_EQ(expect_error(c).code, protocol::ErrorCode::HandshakeRequired);
  EXPECT_TRUE(c.closed_by_service(5s));
}

// NaN and out-of-range poses are rejected with the seq they answer; a RenderRequest
// afterwards renders the last valid pose (state intact).
TEST_F(ServiceFaults, InvalidPoseIsRejectedAndStateStaysIntact) {
  ServiceConnection c(svc_->address(), "nan");
  c.send(test_pose(15.0));
  EXPECT_EQ(c.receive_until<protocol::FrameReady>(60s).pose.lat_deg, 15.0);
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), 95.0, std::numeric_limits<double>::infinity()}) {
    const std::uint64_t seq = c.send(test_pose(bad));
    const auto err = c.receive_until<protocol::Error>(10s);
    EXPECT_EQ(err.code, protocol::ErrorCode::InvalidField);
    EXPECT_EQ(err.answers_seq, seq);
    EXPECT_NE(err.text.find("lat"), std::string::npos) << err.text;
  }
  protocol::RenderRequest rr;
  rr.request_id = 77;
  c.send(rr);
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  EXPECT_EQ(ready.request_id, 77u);
  EXPECT_EQ(ready.pose.lat_deg, 15.0);
}

TEST_F(ServiceFaults, SilentClientDoesNotBlockOthers) {
  RawClient silent(svc_->socket_path());  // connects, never says Hello
  ASSERT_TRUE(silent.connected());
  expect_service_healthy(*svc_, 16.0);
}

TEST_F(ServiceFaults, UnavailableSinkIsRefusedWithoutChangingTheView) {
  ServiceConnection c(svc_->address(), "sink");
  protocol::SetView v;
  v.width = 64;
  v.height = 36;
  v.sinks = protocol::sink::kWindow;  // the test service has no window: not offered in Welcome
  std::uint64_t seq = c.send(v);
  auto err = c.receive_until<protocol::Error>(10s);
  EXPECT_EQ(err.code, protocol::ErrorCode::CapabilityMissing);
  EXPECT_EQ(err.answers_seq, seq);
  v.sinks = protocol::sink::kFile;  // offered, but the directory does not exist
  v.file_dir = "/nonexistent/cloudsvc/frames";
  seq = c.send(v);
  err = c.receive_until<protocol::Error>(10s);
  EXPECT_EQ(err.code, protocol::ErrorCode::SinkUnavailable);
  EXPECT_EQ(err.answers_seq, seq);
  EXPECT_NE(err.text.find("file_dir"), std::string::npos) << err.text;
  c.send(test_pose(17.0));
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  EXPECT_EQ(ready.width, 64u);
  EXPECT_TRUE(ready.shm_slot.has_value());
}

// Bad weather (tile with NaN, wrong data size, inverted bounds; overlapping layers) is
// rejected with an Error naming the field; good weather is accepted and frames go on.
TEST_F(ServiceFaults, BadWeatherIsRejectedGoodWeatherApplies) {
  ServiceConnection c(svc_->address(), "weather");
  protocol::WeatherMapTile tile;
  tile.lat_min_deg = 40;
  tile.lon_min_deg = 0;
  tile.lat_max_deg = 50;
  tile.lon_max_deg = 20;
  tile.width = 4;
  tile.height = 4;
  tile.channels = protocol::tile_channel::kCoverage;
  tile.valid_at_utc_s = 1.782e9;
  tile.data.assign(16, 0.8f);
  auto bad = tile;
  bad.data[5] = std::numeric_limits<float>::quiet_NaN();
  std::uint64_t seq = c.send(bad);
  auto err = c.receive_until<protocol::Error>(10s);
  EXPECT_EQ(err.code, protocol::ErrorCode::InvalidField);
  EXPECT_EQ(err.answers_seq, seq);
  bad = tile;
  bad.data.pop_back();
  seq = c.send(bad);
  EXPECT_EQ(c.receive_until<protocol::Error>(10s).answers_seq, seq);
  bad = tile;
  std::swap(bad.lat_min_deg, bad.lat_max_deg);
  seq = c.send(bad);
  EXPECT_EQ(c.receive_until<protocol::Error>(10s).answers_seq, seq);
  protocol::WeatherLayers layers;
  layers.layers = {protocol::CloudLayer{7, 1000, 2000, 0.5, 0.4, 20, 5, 0}, protocol::CloudLayer{9, 1500, 2500, 0.5, 0.5, 16, 5, 0}};
  seq = c.send(layers);
  err = c.receive_until<protocol::Error>(10s);
  EXPECT_EQ(err.answers_seq, seq);
  EXPECT_NE(err.text.find("layers"), std::string::npos) << err.text;

  c.send(tile);  // valid
  layers.layers.pop_back();
  c.send(layers);  // valid
  c.send(test_pose(18.0));
  const auto ready = c.receive_until<protocol::FrameReady>(60s);
  EXPECT_EQ(ready.pose.lat_deg, 18.0);
}

// SetView.quality_preset: a known preset is applied, an unknown one is refused and the
// view stays as it was.
TEST_F(ServiceFaults, QualityPresetsAreCheckedAndApplied) {
  ServiceConnection c(svc_->address(), "presets");
  protocol::SetView v;
  v.width = 64;
  v.height = 36;
  v.sinks = protocol::sink::kShm;
  v.quality_preset = "no-such-preset";
  const std::uint64_t seq = c.send(v);
  const auto err = c.receive_until<protocol::Error>(10s);
  EXPECT_EQ(err.code, protocol::ErrorCode::UnknownPreset);
  EXPECT_EQ(err.answers_seq, seq);
  v.quality_preset = "low";
  c.send(v);
  c.send(test_pose(19.0));
  EXPECT_EQ(c.receive_until<protocol::FrameReady>(60s).pose.lat_deg, 19.0);
}

}  // namespace
}  // namespace cloudsvc::test
