// Message <-> payload bytes (one FlatBuffers Envelope, schema protocol/cloudsvc.fbs).
// A payload is what one frame carries (framing.h adds the frame header).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/error_code.h"
#include "protocol/messages.h"

namespace cloudsvc::protocol {

// Serialises m as an Envelope with sequence number seq (>= 1; see docs/PROTOCOL.md).
// Writes what it is given without validating it: run validate() first on values that did
// not come from your own code. The result may exceed kMaxPayloadBytes only for tiles and
// strings beyond the protocol's limits, which frame() then refuses.
std::vector<std::uint8_t> encode(const Message& m, std::uint64_t seq);

// Outcome of decode(): a valid message, or an error ready to be sent back.
struct DecodeResult {
  std::uint64_t seq = 0;                     // Envelope.seq; 0 if the payload could not be read
  std::optional<Message> message;            // set exactly when the payload is valid
  ErrorCode error = ErrorCode::Unspecified;  // Malformed, UnknownMessage or InvalidField
  std::string error_text;                    // one line naming the field

  bool ok() const { return message.has_value(); }
  // The Error message answering this payload (only meaningful when !ok()).
  Error to_error() const { return Error{error, error_text, seq}; }
};

// Decodes untrusted bytes: (1) size and FlatBuffers Verifier (bounds, offsets, alignment,
// file identifier "CSVP") -> Malformed; (2) empty or unknown body type -> UnknownMessage;
// (3) validate() and Envelope.seq >= 1 -> InvalidField. Never reads outside `payload`.
DecodeResult decode(std::span<const std::uint8_t> payload);

}  // namespace cloudsvc::protocol
