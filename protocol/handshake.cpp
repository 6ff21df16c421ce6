#include "protocol/handshake.h"

#include <algorithm>

namespace cloudsvc::protocol {
namespace {

std::string version_text(std::uint16_t major, std::uint16_t minor) {
  return std::to_string(major) + "." + std::to_string(minor);
}

HelloVerdict refuse(ErrorCode code, std::string text, std::uint64_t seq) {
  HelloVerdict v;
  v.reply = Error{code, std::move(text), seq};
  return v;
}

// Capability bits a message needs from the service.
std::uint32_t needed_capabilities(const Message& m) {
  if (const auto* view = std::get_if<SetView>(&m)) {
    std::uint32_t need = 0;
    if (view->sinks & sink::kShm) need |= capability::kSinkShm;
    if (view->sinks & sink::kWindow) need |= capability::kSinkWindow;
    if (view->sinks & sink::kFile) need |= capability::kSinkFile;
    return need;
  }
  if (std::holds_alternative<WeatherMapTile>(m)) return capability::kWeatherTiles;
  if (std::holds_alternative<RenderRequest>(m)) return capability::kRenderRequest;
  if (std::holds_alternative<StatsRequest>(m)) return capability::kStats;
  return 0;
}

std::string_view capability_name(std::uint32_t bit) {
  switch (bit) {
    case capability::kSinkShm:
      return "SinkShm";
    case capability::kSinkWindow:
      return "SinkWindow";
    case capability::kSinkFile:
      return "SinkFile";
    case capability::kWeatherTiles:
      return "WeatherTiles";
    case capability::kRenderRequest:
      return "RenderRequest";
    default:
      return "Stats";
  }
}

}  // namespace

HelloVerdict answer_first_message(const DecodeResult& first, const Welcome& welcome) {
  if (!first.ok()) {
    return refuse(first.error, "first message: " + first.error_text, first.seq);
  }
  const auto* hello = std::get_if<Hello>(&*first.message);
  if (hello == nullptr) {
    return refuse(ErrorCode::HandshakeRequired,
                  "first message must be Hello, got " + std::string(message_name(*first.message)),
                  first.seq);
  }
  if (hello->major != welcome.major) {
    return refuse(ErrorCode::VersionMismatch,
                  "client protocol " + version_text(hello->major, hello->minor) +
                      ", service protocol " + version_text(welcome.major, welcome.minor) +
                      " (majors must match)",
                  first.seq);
  }
  HelloVerdict v;
  v.accepted = true;
  v.reply = welcome;
  v.agreed_minor = std::min(hello->minor, welcome.minor);
  v.hello = *hello;
  return v;
}

std::optional<Error> check_client_message(const Message& m, std::uint64_t seq,
                                          std::uint32_t offered) {
  if (sender_of(m) == Sender::Service) {
    return Error{ErrorCode::UnexpectedMessage,
                 std::string(message_name(m)) + " is sent by the service, not by clients", seq};
  }
  if (std::holds_alternative<Hello>(m)) {
    return Error{ErrorCode::UnexpectedMessage, "Hello after the handshake", seq};
  }
  const std::uint32_t missing = needed_capabilities(m) & ~offered;
  if (missing != 0) {
    const std::uint32_t bit = missing & (~missing + 1);  // lowest missing bit
    return Error{ErrorCode::CapabilityMissing,
                 std::string(message_name(m)) + " needs capability " +
                     std::string(capability_name(bit)) + ", which this service lacks",
                 seq};
  }
  return std::nullopt;
}

std::optional<std::string> check_welcome(const DecodeResult& answer, std::uint16_t client_major) {
  if (!answer.ok()) {
    return "service's answer to Hello did not decode: " + answer.error_text;
  }
  if (const auto* err = std::get_if<Error>(&*answer.message)) {
    return "service refused: " + std::string(error_code_name(err->code)) + ": " + err->text;
  }
  const auto* welcome = std::get_if<Welcome>(&*answer.message);
  if (welcome == nullptr) {
    return "expected Welcome, got " + std::string(message_name(*answer.message));
  }
  if (welcome->major != client_major) {
    return "service protocol " + version_text(welcome->major, welcome->minor) + ", client major " +
           std::to_string(client_major) + " (majors must match)";
  }
  return std::nullopt;
}

}  // namespace cloudsvc::protocol
