// Fuzz target: protocol::FrameDecoder (protocol/framing.h), which splits the byte stream of
// every network client into payloads before anything else looks at it.
// Input: byte 0 seeds the sizes of the chunks the stream arrives in, byte 1 picks the
// decoder's payload limit (the protocol's 64 MiB, or 16 B .. 8 KiB so that inputs of a few
// KiB reach the oversize check), the rest is the stream.
// Invariants checked besides the sanitizers':
//  - feeding the stream in chunks (taking payloads after every chunk, as the service does)
//    gives the same payloads, error, error text and byte counts as feeding it at once;
//  - every payload is 1..limit bytes and the frames (frame(payload)) of the payloads,
//    concatenated, are exactly the start of the stream;
//  - without an error every byte is consumed and the unfinished frame is the rest of the
//    stream; with one, the Error{FramingError} the service sends before closing is valid.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/sendable.h"
#include "protocol/framing.h"
#include "protocol/limits.h"

namespace {

using namespace cloudsvc;

struct Outcome {
  std::vector<std::vector<std::uint8_t>> payloads;
  protocol::FramingError error = protocol::FramingError::None;
  std::string error_text;
  std::uint64_t consumed = 0;
  std::size_t partial = 0;

  void finish(protocol::FrameDecoder& d) {
    while (auto p = d.next()) payloads.push_back(std::move(*p));
    error = d.error();
    error_text = d.error_text();
    consumed = d.bytes_consumed();
    partial = d.partial_bytes();
  }
  bool operator==(const Outcome&) const = default;
};

// Chunk sizes 1..64 from a xorshift generator, so one input byte gives many split patterns.
std::size_t next_chunk(std::uint32_t& state) {
  state ^= state << 13;
  state ^= state >> 17;
  state ^= state << 5;
  return 1 + state % 64;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  std::uint32_t chunk_state = 0x9e3779b9u ^ data[0];
  const std::uint32_t limit =
      data[1] < 128 ? protocol::kMaxPayloadBytes : 16u + (data[1] - 128u) * 64u;
  const std::span<const std::uint8_t> stream(data + 2, size - 2);

  protocol::FrameDecoder whole(limit);
  whole.feed(stream);
  Outcome at_once;
  at_once.finish(whole);

  protocol::FrameDecoder chunked(limit);
  Outcome in_chunks;
  for (std::size_t i = 0; i < stream.size();) {
    const std::size_t n = std::min(next_chunk(chunk_state), stream.size() - i);
    chunked.feed(stream.subspan(i, n));
    i += n;
    while (auto p = chunked.next()) in_chunks.payloads.push_back(std::move(*p));
  }
  in_chunks.finish(chunked);
  FUZZ_CHECK(at_once == in_chunks, "FrameDecoder's output depends on how the stream is split");

  std::vector<std::uint8_t> reframed;
  for (const auto& p : at_once.payloads) {
    FUZZ_CHECK(!p.empty() && p.size() <= limit, "a payload outside 1..limit bytes");
    const auto f = protocol::frame(p);
    reframed.insert(reframed.end(), f.begin(), f.end());
  }
  FUZZ_CHECK(reframed.size() <= stream.size() &&
                 std::equal(reframed.begin(), reframed.end(), stream.begin()),
             "the payloads' frames are not the start of the stream");
  FUZZ_CHECK(at_once.consumed <= stream.size(), "more bytes consumed than fed");

  if (at_once.error == protocol::FramingError::None) {
    FUZZ_CHECK(at_once.error_text.empty(), "an error text without an error");
    FUZZ_CHECK(at_once.consumed == stream.size(), "bytes left unconsumed without an error");
    FUZZ_CHECK(reframed.size() + at_once.partial == stream.size(),
               "complete frames plus the unfinished one are not the whole stream");
  } else {
    FUZZ_CHECK(!at_once.error_text.empty(), "a framing error without a text");
    fuzz::check_sendable(
        protocol::Error{protocol::ErrorCode::FramingError, at_once.error_text, 0}, 1,
        "the service's Error{FramingError} before it closes the connection");
  }
  return 0;
}
