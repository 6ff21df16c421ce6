#include "protocol/framing.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace cloudsvc::protocol {
namespace {

// Bytes reserved up front for a payload: a peer that announces 64 MiB and sends nothing
// must not cost 64 MiB; larger payloads grow the buffer as their bytes arrive.
constexpr std::size_t kInitialReserve = 1u << 20;

std::string hex_byte(std::uint8_t b) {
  char buf[8] = {'0', 'x'};
  const auto r = std::to_chars(buf + 2, buf + sizeof buf, b, 16);
  return std::string(buf, r.ptr);
}

}  // namespace

std::array<std::uint8_t, kFrameHeaderBytes> frame_header(std::size_t payload_bytes) {
  if (payload_bytes == 0 || payload_bytes > kMaxPayloadBytes) {
    throw std::length_error("frame payload of " + std::to_string(payload_bytes) +
                            " bytes outside [1, " + std::to_string(kMaxPayloadBytes) + "]");
  }
  const auto n = static_cast<std::uint32_t>(payload_bytes);
  return {kFrameMagic[0],
          kFrameMagic[1],
          kFrameMagic[2],
          kFrameMagic[3],
          static_cast<std::uint8_t>(n),
          static_cast<std::uint8_t>(n >> 8),
          static_cast<std::uint8_t>(n >> 16),
          static_cast<std::uint8_t>(n >> 24)};
}

std::vector<std::uint8_t> frame(std::span<const std::uint8_t> payload) {
  const auto header = frame_header(payload.size());
  std::vector<std::uint8_t> out(header.size() + payload.size());
  std::copy(header.begin(), header.end(), out.begin());
  std::copy(payload.begin(), payload.end(), out.begin() + header.size());
  return out;
}

FrameDecoder::FrameDecoder(std::uint32_t max_payload_bytes)
    : max_payload_(std::clamp<std::uint32_t>(max_payload_bytes, 1, kMaxPayloadBytes)) {}

void FrameDecoder::fail(FramingError e, std::string text) {
  error_ = e;
  error_text_ = std::move(text);
  header_have_ = 0;
  payload_ = {};
}

void FrameDecoder::header_complete() {
  payload_expected_ =
      static_cast<std::uint32_t>(header_[4]) | static_cast<std::uint32_t>(header_[5]) << 8 |
      static_cast<std::uint32_t>(header_[6]) << 16 | static_cast<std::uint32_t>(header_[7]) << 24;
  if (payload_expected_ == 0) {
    fail(FramingError::ZeroLength, "frame length 0 (a payload has at least 1 byte)");
    return;
  }
  if (payload_expected_ > max_payload_) {
    fail(FramingError::Oversize, "frame length " + std::to_string(payload_expected_) +
                                     " bytes above the limit " + std::to_string(max_payload_));
    return;
  }
  payload_.reserve(std::min<std::size_t>(payload_expected_, kInitialReserve));
}

void FrameDecoder::feed(std::span<const std::uint8_t> bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && !failed()) {
    if (header_have_ < kFrameHeaderBytes) {
      const std::uint8_t b = bytes[i++];
      ++consumed_;
      if (header_have_ < kFrameMagic.size() && b != kFrameMagic[header_have_]) {
        fail(FramingError::BadMagic, "bad frame magic byte " + hex_byte(b) + " at header byte " +
                                         std::to_string(header_have_) + ", stream offset " +
                                         std::to_string(consumed_ - 1) + " (expected \"CSV1\")");
        return;
      }
      header_[header_have_++] = b;
      if (header_have_ == kFrameHeaderBytes) header_complete();
      continue;
    }
    const std::size_t take =
        std::min<std::size_t>(payload_expected_ - payload_.size(), bytes.size() - i);
    payload_.insert(payload_.end(), bytes.begin() + i, bytes.begin() + i + take);
    i += take;
    consumed_ += take;
    if (payload_.size() == payload_expected_) {
      ready_.push_back(std::move(payload_));
      payload_ = {};
      header_have_ = 0;
    }
  }
}

std::optional<std::vector<std::uint8_t>> FrameDecoder::next() {
  if (ready_.empty()) return std::nullopt;
  std::vector<std::uint8_t> p = std::move(ready_.front());
  ready_.pop_front();
  return p;
}

}  // namespace cloudsvc::protocol
