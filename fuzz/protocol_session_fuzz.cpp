// Fuzz target: one client connection as the service handles it, without sockets: the bytes
// a network client sends go through FrameDecoder (protocol/framing.h), decode()
// (protocol/codec.h), the handshake answer_first_message() and, after it,
// check_client_message() (protocol/handshake.h), in the order of ClientSession::on_bytes
// and on_payload in service/network_server.cpp. Messages that pass reach the service's
// handler; for the weather ones the conversion to the weather module is checked too.
// Input: byte 0 is the capability bits the service offers (its Welcome), the rest is the
// byte stream of the connection.
// Invariants checked besides the sanitizers':
//  - every reply (Welcome, Errors, the FramingError before closing) is a valid message
//    that survives encode() -> decode() (fuzz/sendable.h);
//  - the first payload is accepted exactly when it is a valid Hello of the service's major
//    version, the reply is then the service's Welcome and sim_client's check_welcome()
//    accepts it; a refusal carries the documented code and check_welcome() refuses it;
//  - after the handshake, a refused message gets an Error answering its seq; a message let
//    through is a client message other than Hello whose capabilities were offered;
//  - a WeatherLayers let through converts to a weather::Weather that weather::validate()
//    accepts and a WeatherMapTile to a weather::MapTile without problem(): the renderer
//    throws on either otherwise (CloudRenderer::set_weather, ::apply_tile). For tiles the
//    protocol applies the same rules (weather/map_tile.h), so this checks the conversion.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <variant>

#include "fuzz/fuzz_check.h"
#include "fuzz/sendable.h"
#include "protocol/codec.h"
#include "protocol/framing.h"
#include "protocol/handshake.h"
#include "protocol/weather_conversion.h"
#include "weather/cloud_layer.h"

namespace {

using namespace cloudsvc;
using protocol::ErrorCode;

// The reply as the client receives it.
protocol::DecodeResult received(const protocol::Message& reply) {
  return protocol::decode(protocol::encode(reply, 1));
}

// The service's side of the handshake; false when the connection closes.
bool handshake(const protocol::DecodeResult& r, const protocol::Welcome& welcome) {
  const protocol::HelloVerdict v = protocol::answer_first_message(r, welcome);
  fuzz::check_sendable(v.reply, 1, "the service's answer to the first message");
  const auto* hello = r.ok() ? std::get_if<protocol::Hello>(&*r.message) : nullptr;
  const bool acceptable = hello != nullptr && hello->major == welcome.major;
  FUZZ_CHECK(v.accepted == acceptable, "answer_first_message() accepts the wrong first messages");
  if (!v.accepted) {
    const auto* err = std::get_if<protocol::Error>(&v.reply);
    FUZZ_CHECK(err != nullptr, "a refused handshake is not answered with an Error");
    const ErrorCode expected = !r.ok() ? r.error
                               : hello == nullptr ? ErrorCode::HandshakeRequired
                                                  : ErrorCode::VersionMismatch;
    FUZZ_CHECK(err->code == expected, "a refused handshake has the wrong error code");
    FUZZ_CHECK(protocol::check_welcome(received(v.reply)).has_value(),
               "sim_client would go on after the service refused its Hello");
    return false;
  }
  FUZZ_CHECK(v.reply == protocol::Message(welcome), "the accepted handshake's reply is not the Welcome");
  FUZZ_CHECK(v.hello == *hello, "the verdict's Hello is not the client's");
  FUZZ_CHECK(v.agreed_minor == std::min(hello->minor, welcome.minor), "agreed minor is not the smaller one");
  FUZZ_CHECK(!protocol::check_welcome(received(v.reply)).has_value(),
             "sim_client refuses the Welcome of an accepted handshake");
  return true;
}

// What the service's handler would be given, checked against the weather module.
void check_handled(const protocol::Message& m, std::uint32_t offered) {
  FUZZ_CHECK(protocol::sender_of(m) != protocol::Sender::Service,
             "a service-only message got past check_client_message()");
  FUZZ_CHECK(!std::holds_alternative<protocol::Hello>(m), "a second Hello got through");
  if (const auto* layers = std::get_if<protocol::WeatherLayers>(&m)) {
    const std::string problem = weather::validate(to_weather(*layers));
    if (!problem.empty()) std::fprintf(stderr, "weather::validate: %s\n", problem.c_str());
    FUZZ_CHECK(problem.empty(), "WeatherLayers passes the protocol but not weather::validate()");
  }
  if (const auto* tile = std::get_if<protocol::WeatherMapTile>(&m)) {
    FUZZ_CHECK(offered & protocol::capability::kWeatherTiles, "a tile got through without the capability");
    const std::string problem = to_map_tile(*tile).problem();
    if (!problem.empty()) std::fprintf(stderr, "MapTile::problem: %s\n", problem.c_str());
    FUZZ_CHECK(problem.empty(), "WeatherMapTile passes the protocol but not MapTile::problem()");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  protocol::Welcome welcome;  // as `cloudsvc serve` builds it, with fuzzed capabilities
  welcome.service_version = "0.1.0";
  welcome.capabilities = data[0] & protocol::capability::kAll;
  welcome.limits = protocol::protocol_limits();

  protocol::FrameDecoder decoder(welcome.limits.max_payload_bytes);
  decoder.feed(std::span(data + 1, size - 1));
  bool handshaken = false;
  while (auto payload = decoder.next()) {
    const protocol::DecodeResult r = protocol::decode(*payload);
    if (!handshaken) {
      if (!handshake(r, welcome)) return 0;  // the service closes the connection
      handshaken = true;
      continue;
    }
    if (!r.ok()) {
      fuzz::check_sendable(r.to_error(), 2, "the service's Error for a refused payload");
      continue;
    }
    if (auto err = protocol::check_client_message(*r.message, r.seq, welcome.capabilities)) {
      fuzz::check_sendable(*err, 2, "the service's Error for a message it does not take");
      FUZZ_CHECK(err->answers_seq == r.seq, "the Error does not answer the message's seq");
      continue;
    }
    check_handled(*r.message, welcome.capabilities);
  }
  if (decoder.failed()) {
    fuzz::check_sendable(protocol::Error{ErrorCode::FramingError, decoder.error_text(), 0}, 2,
                         "the service's Error{FramingError} before it closes the connection");
  }
  return 0;
}
