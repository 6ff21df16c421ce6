// Fuzz target: protocol::decode() (protocol/codec.h) on untrusted payload bytes, the first
// thing the service does with every frame a network client sends, and sim_client's check
// of the service's answer to its Hello (protocol::check_welcome, protocol/handshake.h).
// Invariants checked besides the sanitizers':
//  - an accepted payload holds a message that validate() accepts, its seq is >= 1, and the
//    message re-encodes and decodes to the same seq and value;
//  - a refused payload gets Malformed, UnknownMessage or InvalidField with a text, and the
//    Error the service sends back for it (DecodeResult::to_error) is a valid message;
//  - the result does not depend on the payload's alignment (decode() copies unaligned
//    input before the FlatBuffers verifier sees it);
//  - check_welcome() accepts exactly a decodable Welcome with the client's major version.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/sendable.h"
#include "protocol/codec.h"
#include "protocol/handshake.h"
#include "protocol/validate.h"

namespace {

using namespace cloudsvc;
using protocol::ErrorCode;

bool same_result(const protocol::DecodeResult& a, const protocol::DecodeResult& b) {
  return a.seq == b.seq && a.message == b.message && a.error == b.error &&
         a.error_text == b.error_text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> payload(data, size);
  const protocol::DecodeResult r = protocol::decode(payload);

  if (r.ok()) {
    FUZZ_CHECK(r.seq >= 1, "an accepted Envelope has seq 0");
    FUZZ_CHECK(!protocol::validate(*r.message), "decode() accepted a message validate() refuses");
    fuzz::check_sendable(*r.message, r.seq, "decoded message");
  } else {
    FUZZ_CHECK(!r.message, "a refused payload still carries a message");
    FUZZ_CHECK(r.error == ErrorCode::Malformed || r.error == ErrorCode::UnknownMessage ||
                   r.error == ErrorCode::InvalidField,
               "decode() failed with an error code it does not document");
    FUZZ_CHECK(!r.error_text.empty(), "decode() failed without saying why");
    fuzz::check_sendable(r.to_error(), 1, "the service's Error for a refused payload");
  }

  // The same bytes one byte off 8-byte alignment (libFuzzer's own buffer is aligned).
  std::vector<std::uint8_t> shifted(size + 1);
  if (size > 0) std::memcpy(shifted.data() + 1, data, size);
  const protocol::DecodeResult s = protocol::decode(std::span(shifted.data() + 1, size));
  FUZZ_CHECK(same_result(r, s), "decode() depends on the payload's alignment");

  const auto refusal = protocol::check_welcome(r);
  const auto* welcome = r.ok() ? std::get_if<protocol::Welcome>(&*r.message) : nullptr;
  const bool acceptable = welcome != nullptr && welcome->major == protocol::kProtocolMajor;
  FUZZ_CHECK(acceptable == !refusal.has_value(),
             "check_welcome() disagrees with what a usable Welcome is");
  FUZZ_CHECK(!refusal || !refusal->empty(), "check_welcome() refuses without saying why");
  return 0;
}
