// check_sendable(): what every message this project puts on the wire must satisfy so that
// the peer can read it. The service answers hostile input with Error messages (decode
// errors, handshake refusals, framing errors), so a fuzz target that makes the service or
// a client produce a message checks it here: validate() accepts it, and encode() followed
// by decode() gives back the same sequence number and value.
#pragma once

#include <cstdint>
#include <cstdio>

#include "fuzz/fuzz_check.h"
#include "protocol/codec.h"
#include "protocol/validate.h"

namespace cloudsvc::fuzz {

inline void check_sendable(const protocol::Message& m, std::uint64_t seq, const char* what) {
  if (const auto problem = protocol::validate(m)) {
    std::fprintf(stderr, "%s: %s\n", what, problem->c_str());
    FUZZ_CHECK(false, "a message the project sends fails validate(): the peer would refuse it");
  }
  const protocol::DecodeResult back = protocol::decode(protocol::encode(m, seq));
  if (!back.ok()) std::fprintf(stderr, "%s: %s\n", what, back.error_text.c_str());
  FUZZ_CHECK(back.ok(), "a valid message does not decode after encode()");
  FUZZ_CHECK(back.seq == seq && *back.message == m, "encode() -> decode() changes a valid message");
}

}  // namespace cloudsvc::fuzz
