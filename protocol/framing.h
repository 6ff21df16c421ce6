// Frames on a byte stream (TCP or a Unix stream socket). Every frame is
//
//   offset  size  field
//   0       4     magic "CSV1" = 0x43 0x53 0x56 0x31 (the '1' is the framing version)
//   4       4     payload length, unsigned 32-bit little-endian, 1..kMaxPayloadBytes
//   8       n     payload: one FlatBuffers Envelope (codec.h)
//
// There is no per-frame version field: the protocol version is agreed once in the
// Hello/Welcome handshake, FlatBuffers tables are forward compatible, and a different
// framing would get a different magic. The 8-byte header keeps a payload that follows an
// 8-aligned frame start 8-aligned, as FlatBuffers' doubles like.
// A bad magic, a zero length or a length above the limit is fatal: the receiver sends
// Error{FramingError} if it can and closes the connection (the stream cannot resync).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/limits.h"

namespace cloudsvc::protocol {

// TCP port a service listens on unless told otherwise (`cloudsvc serve` listens on
// tcp://127.0.0.1:7420 by default; Unix sockets have no default path).
inline constexpr std::uint16_t kDefaultTcpPort = 7420;

inline constexpr std::array<std::uint8_t, 4> kFrameMagic = {'C', 'S', 'V', '1'};
inline constexpr std::size_t kFrameHeaderBytes = 8;
// kMaxPayloadBytes (limits.h, 64 MiB) bounds the length field.

// The 8 header bytes of a frame carrying payload_bytes (1..kMaxPayloadBytes).
// Throws std::length_error outside that range.
std::array<std::uint8_t, kFrameHeaderBytes> frame_header(std::size_t payload_bytes);

// Header + payload in one buffer. Throws std::length_error like frame_header().
std::vector<std::uint8_t> frame(std::span<const std::uint8_t> payload);

enum class FramingError {
  None,
  BadMagic,    // a header byte differs from "CSV1"
  ZeroLength,  // length field 0
  Oversize,    // length field above the decoder's limit
};

// Splits a byte stream into payloads. Feed it whatever the socket returned (any split,
// down to one byte at a time); take complete payloads with next(). A bad header is
// detected as early as possible (a wrong magic at its first wrong byte, an oversize length
// before any of its payload is buffered) and stops the decoder for good: feed() then
// ignores its input and the connection must be dropped. Payloads completed before the
// error are still returned by next().
class FrameDecoder {
 public:
  // max_payload_bytes: the limit this side advertises, clamped to [1, kMaxPayloadBytes].
  explicit FrameDecoder(std::uint32_t max_payload_bytes = kMaxPayloadBytes);

  void feed(std::span<const std::uint8_t> bytes);

  // The oldest complete payload not yet taken, or nullopt.
  std::optional<std::vector<std::uint8_t>> next();

  bool failed() const { return error_ != FramingError::None; }
  FramingError error() const { return error_; }
  // One line describing the error ("bad frame magic 0x47 at header byte 0 (expected
  // 'CSV1')"), empty when !failed().
  const std::string& error_text() const { return error_text_; }

  // Total bytes consumed so far, and bytes of the frame in progress (header + payload).
  std::uint64_t bytes_consumed() const { return consumed_; }
  std::size_t partial_bytes() const { return header_have_ + payload_.size(); }

 private:
  void fail(FramingError e, std::string text);
  void header_complete();

  std::uint32_t max_payload_;
  std::array<std::uint8_t, kFrameHeaderBytes> header_{};
  std::size_t header_have_ = 0;         // header bytes of the current frame received
  std::uint32_t payload_expected_ = 0;  // length field of the current frame
  std::vector<std::uint8_t> payload_;   // payload bytes of the current frame received
  std::deque<std::vector<std::uint8_t>> ready_;
  std::uint64_t consumed_ = 0;
  FramingError error_ = FramingError::None;
  std::string error_text_;
};

}  // namespace cloudsvc::protocol
