// Error codes of the Error message (values as in cloudsvc.fbs, enum ErrorCode).
// Fatal codes: the sender of the Error closes the connection right after it.
#pragma once

#include <cstdint>
#include <string_view>

namespace cloudsvc::protocol {

enum class ErrorCode : std::uint16_t {
  Unspecified = 0,
  Malformed = 1,           // payload failed the FlatBuffers verifier
  InvalidField = 2,        // a field is NaN/Inf, out of range or inconsistent
  UnknownMessage = 3,      // empty or unknown Body type (e.g. from a newer minor)
  UnexpectedMessage = 4,   // valid message in the wrong direction or state
  HandshakeRequired = 5,   // first message was not Hello (fatal)
  VersionMismatch = 6,     // protocol majors differ (fatal)
  FramingError = 7,        // bad magic, zero or oversize length (fatal)
  UnknownPreset = 8,       // SetView.quality_preset names no preset
  SinkUnavailable = 9,     // a requested sink cannot be opened
  CapabilityMissing = 10,  // the message needs a capability the service does not offer
  Busy = 11,               // connection refused, e.g. too many clients (fatal)
  RenderFailed = 12,       // the renderer failed for this frame
  Internal = 13,           // bug in the service
  Overloaded = 14,         // refused: a per-client or memory bound is reached; retry later (minor 1)
  IdleTimeout = 15,        // the client sent nothing for the service's idle timeout (fatal; minor 1)
};

// "InvalidField", ...; "Unknown" for values outside the enum (a newer peer's codes).
std::string_view error_code_name(ErrorCode code);

// True for HandshakeRequired, VersionMismatch, FramingError, Busy and IdleTimeout.
bool is_fatal(ErrorCode code);

}  // namespace cloudsvc::protocol
