// Connection rules (docs/PROTOCOL.md, "Handshake" and "Errors"), as pure functions that
// the service and clients apply to decoded payloads.
//
//   1. The client's first payload must be a valid Hello. Anything else: the service
//      answers Error (HandshakeRequired for another message, the decode error code for a
//      payload that does not decode) and closes.
//   2. Major versions must be equal, else Error{VersionMismatch} and close. Minor versions
//      may differ; both sides use the smaller one.
//   3. The service answers Welcome (its version, capabilities, limits). Afterwards it
//      rejects, without closing, messages a client may not send (UnexpectedMessage) and
//      messages needing a capability it did not offer (CapabilityMissing).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "protocol/codec.h"
#include "protocol/messages.h"

namespace cloudsvc::protocol {

// Service side: what to do with the first payload of a connection.
struct HelloVerdict {
  bool accepted = false;
  Message reply;                   // Welcome when accepted, else a fatal Error
  std::uint16_t agreed_minor = 0;  // min(client minor, service minor) when accepted
  Hello hello;                     // the client's Hello when accepted
};
// `welcome` is the service's own Welcome (version, capabilities, limits).
HelloVerdict answer_first_message(const DecodeResult& first, const Welcome& welcome);

// Service side, after the handshake: nullopt when the service should act on `m`;
// otherwise the (non-fatal) Error to send back. `offered` are the capability bits the
// service's Welcome advertised.
std::optional<Error> check_client_message(const Message& m, std::uint64_t seq,
                                          std::uint32_t offered);

// Client side: nullopt when `answer` (the service's first payload) is a Welcome with the
// client's major version; otherwise one line saying why the client must give up.
std::optional<std::string> check_welcome(const DecodeResult& answer,
                                         std::uint16_t client_major = kProtocolMajor);

}  // namespace cloudsvc::protocol
