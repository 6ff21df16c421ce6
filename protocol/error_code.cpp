#include "protocol/error_code.h"

namespace cloudsvc::protocol {

std::string_view error_code_name(ErrorCode code) {
  switch (code) {
    case ErrorCode::Unspecified:
      return "Unspecified";
    case ErrorCode::Malformed:
      return "Malformed";
    case ErrorCode::InvalidField:
      return "InvalidField";
    case ErrorCode::UnknownMessage:
      return "UnknownMessage";
    case ErrorCode::UnexpectedMessage:
      return "UnexpectedMessage";
    case ErrorCode::HandshakeRequired:
      return "HandshakeRequired";
    case ErrorCode::VersionMismatch:
      return "VersionMismatch";
    case ErrorCode::FramingError:
      return "FramingError";
    case ErrorCode::UnknownPreset:
      return "UnknownPreset";
    case ErrorCode::SinkUnavailable:
      return "SinkUnavailable";
    case ErrorCode::CapabilityMissing:
      return "CapabilityMissing";
    case ErrorCode::Busy:
      return "Busy";
    case ErrorCode::RenderFailed:
      return "RenderFailed";
    case ErrorCode::Internal:
      return "Internal";
    case ErrorCode::Overloaded:
      return "Overloaded";
    case ErrorCode::IdleTimeout:
      return "IdleTimeout";
  }
  return "Unknown";
}

bool is_fatal(ErrorCode code) {
  return code == ErrorCode::HandshakeRequired || code == ErrorCode::VersionMismatch ||
         code == ErrorCode::FramingError || code == ErrorCode::Busy ||
         code == ErrorCode::IdleTimeout;
}

}  // namespace cloudsvc::protocol
