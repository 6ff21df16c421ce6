// Framing: header layout, chunking at every split point, byte-at-a-time feeding, and the
// fatal errors (bad magic, zero length, oversize length).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

#include "protocol/framing.h"

namespace cloudsvc::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes payload_of(std::size_t n, std::uint8_t seed) {
  Bytes p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = static_cast<std::uint8_t>(seed + 13 * i);
  return p;
}

// Three frames of different sizes back to back.
struct Stream {
  std::vector<Bytes> payloads = {payload_of(1, 1), payload_of(37, 2), payload_of(12, 3)};
  Bytes bytes;
  Stream() {
    for (const Bytes& p : payloads) {
      const Bytes f = frame(p);
      bytes.insert(bytes.end(), f.begin(), f.end());
    }
  }
};

std::vector<Bytes> drain(FrameDecoder& d) {
  std::vector<Bytes> out;
  while (auto p = d.next()) out.push_back(std::move(*p));
  return out;
}

std::span<const std::uint8_t> slice(const Bytes& b, std::size_t from, std::size_t to) {
  return std::span<const std::uint8_t>(b).subspan(from, to - from);
}

TEST(ProtocolFraming, HeaderIsMagicThenLittleEndianLength) {
  const auto h = frame_header(0x01020304);
  const std::array<std::uint8_t, 8> expected = {0x43, 0x53, 0x56, 0x31, 0x04, 0x03, 0x02, 0x01};
  EXPECT_EQ(h, expected);
  const Bytes f = frame(Bytes{0xaa, 0xbb});
  EXPECT_EQ(f, (Bytes{'C', 'S', 'V', '1', 2, 0, 0, 0, 0xaa, 0xbb}));
}

TEST(ProtocolFraming, EncoderRefusesEmptyAndOversizePayloads) {
  EXPECT_THROW(frame_header(0), std::length_error);
  EXPECT_THROW(frame_header(std::size_t{kMaxPayloadBytes} + 1), std::length_error);
  EXPECT_NO_THROW(frame_header(kMaxPayloadBytes));
  EXPECT_THROW(frame(Bytes{}), std::length_error);
}

TEST(ProtocolFraming, MultipleFramesInOneChunk) {
  const Stream s;
  FrameDecoder d;
  d.feed(s.bytes);
  EXPECT_FALSE(d.failed());
  EXPECT_EQ(drain(d), s.payloads);
  EXPECT_EQ(d.partial_bytes(), 0u);
  EXPECT_EQ(d.bytes_consumed(), s.bytes.size());
}

TEST(ProtocolFraming, OneByteAtATime) {
  const Stream s;
  FrameDecoder d;
  std::vector<Bytes> got;
  for (std::size_t i = 0; i < s.bytes.size(); ++i) {
    d.feed(slice(s.bytes, i, i + 1));
    for (auto& p : drain(d)) got.push_back(std::move(p));
    ASSERT_FALSE(d.failed()) << d.error_text();
  }
  EXPECT_EQ(got, s.payloads);
}

TEST(ProtocolFraming, EverySplitIntoTwoAndThreeChunks) {
  const Stream s;
  const std::size_t n = s.bytes.size();
  for (std::size_t a = 0; a <= n; ++a) {
    FrameDecoder d;
    d.feed(slice(s.bytes, 0, a));
    d.feed(slice(s.bytes, a, n));
    ASSERT_EQ(drain(d), s.payloads) << "split at " << a;
    for (std::size_t b = a; b <= n; ++b) {
      FrameDecoder d3;
      d3.feed(slice(s.bytes, 0, a));
      d3.feed(slice(s.bytes, a, b));
      d3.feed(slice(s.bytes, b, n));
      ASSERT_EQ(drain(d3), s.payloads) << "splits at " << a << ", " << b;
    }
  }
}

TEST(ProtocolFraming, PartialFrameIsHeldUntilComplete) {
  const Bytes f = frame(payload_of(100, 9));
  FrameDecoder d;
  d.feed(slice(f, 0, 50));
  EXPECT_FALSE(d.next().has_value());
  EXPECT_EQ(d.partial_bytes(), 50u);
  d.feed(slice(f, 50, f.size()));
  EXPECT_EQ(d.next(), payload_of(100, 9));
  EXPECT_EQ(d.partial_bytes(), 0u);
}

TEST(ProtocolFraming, RandomChunkingOfManyFrames) {
  std::mt19937 rng(99);
  std::vector<Bytes> payloads;
  Bytes stream;
  for (int i = 0; i < 200; ++i) {
    payloads.push_back(payload_of(1 + rng() % 3000, static_cast<std::uint8_t>(i)));
    const Bytes f = frame(payloads.back());
    stream.insert(stream.end(), f.begin(), f.end());
  }
  FrameDecoder d;
  std::vector<Bytes> got;
  for (std::size_t at = 0; at < stream.size();) {
    const std::size_t len = std::min<std::size_t>(rng() % 5000, stream.size() - at);
    d.feed(slice(stream, at, at + len));
    at += len;
    for (auto& p : drain(d)) got.push_back(std::move(p));
  }
  EXPECT_FALSE(d.failed());
  EXPECT_EQ(got, payloads);
}

TEST(ProtocolFraming, BadMagicAtEachHeaderByteIsFatalAtOnce) {
  for (std::size_t pos = 0; pos < 4; ++pos) {
    Bytes f = frame(payload_of(10, 1));
    f[pos] ^= 0x20;  // 'C' -> 'c', ...
    FrameDecoder d;
    for (std::size_t i = 0; i <= pos; ++i) {
      EXPECT_FALSE(d.failed());
      d.feed(slice(f, i, i + 1));
    }
    ASSERT_TRUE(d.failed()) << "wrong byte " << pos << " not noticed when it arrived";
    EXPECT_EQ(d.error(), FramingError::BadMagic);
    EXPECT_NE(d.error_text().find("header byte " + std::to_string(pos)), std::string::npos)
        << d.error_text();
    d.feed(slice(f, pos + 1, f.size()));
    EXPECT_FALSE(d.next().has_value());
  }
}

TEST(ProtocolFraming, HttpRequestIsRejectedOnItsFirstByte) {
  const std::string get = "GET / HTTP/1.1\r\nHost: x\r\n\r\n";
  FrameDecoder d;
  d.feed(Bytes(get.begin(), get.end()));
  EXPECT_EQ(d.error(), FramingError::BadMagic);
  EXPECT_EQ(d.bytes_consumed(), 1u);
  EXPECT_EQ(d.error_text(),
            "bad frame magic byte 0x47 at header byte 0, stream offset 0 (expected \"CSV1\")");
}

TEST(ProtocolFraming, OversizeLengthIsFatalBeforeAnyPayloadArrives) {
  auto header = frame_header(1);
  const std::uint32_t too_big = kMaxPayloadBytes + 1;
  std::memcpy(header.data() + 4, &too_big, 4);  // little-endian host
  FrameDecoder d;
  d.feed(header);
  EXPECT_TRUE(d.failed());
  EXPECT_EQ(d.error(), FramingError::Oversize);
  EXPECT_EQ(d.partial_bytes(), 0u);

  const std::array<std::uint8_t, 8> max_u32 = {'C', 'S', 'V', '1', 0xff, 0xff, 0xff, 0xff};
  FrameDecoder d2;
  d2.feed(max_u32);
  EXPECT_EQ(d2.error(), FramingError::Oversize);
}

TEST(ProtocolFraming, DecoderLimitIsInclusiveAndConfigurable) {
  FrameDecoder small(100);
  small.feed(frame(payload_of(100, 1)));
  EXPECT_FALSE(small.failed());
  EXPECT_EQ(small.next(), payload_of(100, 1));
  small.feed(frame(payload_of(101, 1)));
  EXPECT_EQ(small.error(), FramingError::Oversize);
  EXPECT_NE(small.error_text().find("101"), std::string::npos);

  // A limit above the protocol's is clamped to it.
  FrameDecoder clamped(0xffffffffu);
  auto header = frame_header(1);
  const std::uint32_t too_big = kMaxPayloadBytes + 1;
  std::memcpy(header.data() + 4, &too_big, 4);
  clamped.feed(header);
  EXPECT_EQ(clamped.error(), FramingError::Oversize);
}

TEST(ProtocolFraming, LargestPayloadPasses) {
  Bytes big(kMaxPayloadBytes, 0x5a);
  big.back() = 0x77;
  const auto header = frame_header(big.size());
  FrameDecoder d;
  d.feed(header);
  for (std::size_t at = 0; at < big.size(); at += 1 << 20) {
    d.feed(slice(big, at, std::min(big.size(), at + (1 << 20))));
  }
  ASSERT_FALSE(d.failed()) << d.error_text();
  const auto got = d.next();
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->size(), big.size());
  EXPECT_EQ(got->back(), 0x77);
}

TEST(ProtocolFraming, ZeroLengthIsFatal) {
  const std::array<std::uint8_t, 8> zero = {'C', 'S', 'V', '1', 0, 0, 0, 0};
  FrameDecoder d;
  d.feed(zero);
  EXPECT_EQ(d.error(), FramingError::ZeroLength);
}

TEST(ProtocolFraming, FramesBeforeAnErrorAreKeptAndNothingAfterIt) {
  const Stream s;
  Bytes stream = frame(payload_of(5, 1));
  const Bytes bad = {'C', 'S', 'X', '1'};
  stream.insert(stream.end(), bad.begin(), bad.end());
  stream.insert(stream.end(), s.bytes.begin(), s.bytes.end());
  FrameDecoder d;
  d.feed(stream);
  EXPECT_EQ(d.error(), FramingError::BadMagic);
  EXPECT_EQ(d.bytes_consumed(), 13u + 3u);
  EXPECT_EQ(drain(d), std::vector<Bytes>{payload_of(5, 1)});
  d.feed(s.bytes);  // ignored for good
  EXPECT_TRUE(drain(d).empty());
  EXPECT_TRUE(d.failed());
}

}  // namespace
}  // namespace cloudsvc::protocol
