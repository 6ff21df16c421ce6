// Handshake and per-message session rules (protocol/handshake.h), on decoded payloads.
#include <gtest/gtest.h>

#include "protocol/codec.h"
#include "protocol/framing.h"
#include "protocol/handshake.h"

namespace cloudsvc::protocol {
namespace {

Welcome service_welcome(std::uint32_t caps = capability::kAll) {
  Welcome w;
  w.service_version = "0.1.0";
  w.capabilities = caps;
  return w;
}

DecodeResult wire_trip(const Message& m, std::uint64_t seq) { return decode(encode(m, seq)); }

TEST(ProtocolHandshake, HelloWithSameMajorIsWelcomed) {
  const Hello hello{kProtocolMajor, static_cast<std::uint16_t>(kProtocolMinor + 4), "sim", 0};
  const HelloVerdict v = answer_first_message(wire_trip(hello, 1), service_welcome());
  ASSERT_TRUE(v.accepted);
  EXPECT_EQ(std::get<Welcome>(v.reply), service_welcome());
  EXPECT_EQ(v.agreed_minor, kProtocolMinor);
  EXPECT_EQ(v.hello, hello);
}

TEST(ProtocolHandshake, AgreedMinorIsTheSmallerOne) {
  Welcome w = service_welcome();
  w.minor = 5;
  const HelloVerdict v = answer_first_message(wire_trip(Hello{kProtocolMajor, 2, "", 0}, 1), w);
  ASSERT_TRUE(v.accepted);
  EXPECT_EQ(v.agreed_minor, 2);
}

TEST(ProtocolHandshake, MajorMismatchIsFatal) {
  const Hello hello{static_cast<std::uint16_t>(kProtocolMajor + 1), 0, "future", 0};
  const HelloVerdict v = answer_first_message(wire_trip(hello, 3), service_welcome());
  EXPECT_FALSE(v.accepted);
  const Error& e = std::get<Error>(v.reply);
  EXPECT_EQ(e.code, ErrorCode::VersionMismatch);
  EXPECT_TRUE(is_fatal(e.code));
  EXPECT_EQ(e.answers_seq, 3u);
  EXPECT_EQ(e.text, "client protocol 2.0, service protocol 1." + std::to_string(kProtocolMinor) + " (majors must match)");
}

TEST(ProtocolHandshake, FirstMessageMustBeHello) {
  Pose p;
  const HelloVerdict v = answer_first_message(wire_trip(p, 1), service_welcome());
  EXPECT_FALSE(v.accepted);
  const Error& e = std::get<Error>(v.reply);
  EXPECT_EQ(e.code, ErrorCode::HandshakeRequired);
  EXPECT_TRUE(is_fatal(e.code));
  EXPECT_EQ(e.text, "first message must be Hello, got Pose");
}

TEST(ProtocolHandshake, UndecodableFirstPayloadIsRefusedWithItsDecodeError) {
  const std::vector<std::uint8_t> junk(32, 0xab);
  const HelloVerdict v = answer_first_message(decode(junk), service_welcome());
  EXPECT_FALSE(v.accepted);
  EXPECT_EQ(std::get<Error>(v.reply).code, ErrorCode::Malformed);

  const Hello bad_name{kProtocolMajor, 0, "bad\xff", 0};
  const HelloVerdict w = answer_first_message(wire_trip(bad_name, 4), service_welcome());
  EXPECT_FALSE(w.accepted);
  EXPECT_EQ(std::get<Error>(w.reply).code, ErrorCode::InvalidField);
  EXPECT_EQ(std::get<Error>(w.reply).answers_seq, 4u);
}

TEST(ProtocolSession, ServiceMessagesAndSecondHelloAreUnexpected) {
  for (const Message& m :
       {Message(Welcome{}), Message(FrameReady{}), Message(Stats{}), Message(Hello{})}) {
    const auto e = check_client_message(m, 9, capability::kAll);
    ASSERT_TRUE(e.has_value()) << message_name(m);
    EXPECT_EQ(e->code, ErrorCode::UnexpectedMessage);
    EXPECT_FALSE(is_fatal(e->code));
    EXPECT_EQ(e->answers_seq, 9u);
  }
  for (const Message& m :
       {Message(Pose{}), Message(SetView{}), Message(SetTime{}), Message(WeatherLayers{}),
        Message(Error{}), Message(RenderRequest{1}), Message(StatsRequest{})}) {
    EXPECT_EQ(check_client_message(m, 9, capability::kAll), std::nullopt) << message_name(m);
  }
}

TEST(ProtocolSession, MessagesNeedTheirCapabilities) {
  const std::uint32_t only_shm = capability::kSinkShm;
  SetView view;
  view.sinks = sink::kShm;
  EXPECT_EQ(check_client_message(view, 1, only_shm), std::nullopt);
  view.sinks = sink::kShm | sink::kWindow;
  auto e = check_client_message(view, 2, only_shm);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->code, ErrorCode::CapabilityMissing);
  EXPECT_EQ(e->text, "SetView needs capability SinkWindow, which this service lacks");
  view.sinks = sink::kFile;
  EXPECT_NE(check_client_message(view, 2, only_shm)->text.find("SinkFile"), std::string::npos);

  EXPECT_EQ(check_client_message(WeatherMapTile{}, 3, only_shm)->code,
            ErrorCode::CapabilityMissing);
  EXPECT_EQ(check_client_message(RenderRequest{1}, 3, only_shm)->code,
            ErrorCode::CapabilityMissing);
  EXPECT_EQ(check_client_message(StatsRequest{}, 3, only_shm)->code, ErrorCode::CapabilityMissing);
  EXPECT_EQ(check_client_message(Pose{}, 3, 0), std::nullopt);
}

TEST(ProtocolClient, ChecksTheServicesAnswer) {
  EXPECT_EQ(check_welcome(wire_trip(service_welcome(), 1)), std::nullopt);

  Welcome other = service_welcome();
  other.major = kProtocolMajor + 1;
  const auto mismatch = check_welcome(wire_trip(other, 1));
  ASSERT_TRUE(mismatch.has_value());
  EXPECT_NE(mismatch->find("majors must match"), std::string::npos);

  const auto refused = check_welcome(wire_trip(Error{ErrorCode::Busy, "too many clients", 1}, 1));
  EXPECT_EQ(refused, "service refused: Busy: too many clients");

  EXPECT_EQ(check_welcome(wire_trip(Stats{}, 1)), "expected Welcome, got Stats");
  EXPECT_TRUE(check_welcome(decode(std::vector<std::uint8_t>(4, 0))).has_value());
}

// A whole exchange through framing and codec, as a client and the service would do it.
TEST(ProtocolSession, HandshakeThroughFramesFedByteByByte) {
  std::vector<std::uint8_t> client_stream;
  auto send = [&](const Message& m, std::uint64_t seq) {
    const auto f = frame(encode(m, seq));
    client_stream.insert(client_stream.end(), f.begin(), f.end());
  };
  send(Hello{kProtocolMajor, kProtocolMinor, "test", capability::kSinkShm}, 1);
  Pose pose;
  pose.lat_deg = 47.4, pose.lon_deg = 8.5, pose.alt_m = 1500;
  send(pose, 2);
  send(StatsRequest{}, 3);

  FrameDecoder decoder;
  std::vector<DecodeResult> received;
  for (std::uint8_t byte : client_stream) {
    decoder.feed(std::span(&byte, 1));
    while (auto p = decoder.next()) received.push_back(decode(*p));
  }
  ASSERT_EQ(received.size(), 3u);
  const Welcome welcome = service_welcome(capability::kSinkShm);
  ASSERT_TRUE(answer_first_message(received[0], welcome).accepted);
  ASSERT_TRUE(received[1].ok());
  EXPECT_EQ(check_client_message(*received[1].message, received[1].seq, welcome.capabilities),
            std::nullopt);
  EXPECT_EQ(std::get<Pose>(*received[1].message), pose);
  const auto e = check_client_message(*received[2].message, received[2].seq, welcome.capabilities);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->code, ErrorCode::CapabilityMissing);
  EXPECT_EQ(e->answers_seq, 3u);
}

TEST(ProtocolErrors, NamesAndFatality) {
  EXPECT_EQ(error_code_name(ErrorCode::InvalidField), "InvalidField");
  EXPECT_EQ(error_code_name(ErrorCode{999}), "Unknown");
  int fatal = 0;
  for (int c = 0; c <= static_cast<int>(ErrorCode::IdleTimeout); ++c) {
    EXPECT_NE(error_code_name(static_cast<ErrorCode>(c)), "Unknown") << c;
    fatal += is_fatal(static_cast<ErrorCode>(c));
  }
  EXPECT_EQ(fatal, 5);
  EXPECT_FALSE(is_fatal(ErrorCode::Overloaded)) << "a refused request leaves the connection open";
  EXPECT_TRUE(is_fatal(ErrorCode::IdleTimeout));
}

}  // namespace
}  // namespace cloudsvc::protocol
