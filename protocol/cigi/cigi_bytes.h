// Byte-order aware reading and writing of CIGI packet fields. CIGI messages travel in the
// sender's byte order, told by the magic number of the first packet (cigi_packets.h).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace cloudsvc::cigi {

enum class ByteOrder : std::uint8_t { Big, Little };

// The order of this machine's integers and floats.
inline constexpr ByteOrder kNativeOrder = std::endian::native == std::endian::little ? ByteOrder::Little : ByteOrder::Big;

// Fields of one packet, read at byte offsets from its start (the caller has checked that the
// packet holds `size` bytes).
class FieldReader {
 public:
  FieldReader(std::span<const std::uint8_t> packet, ByteOrder order) : p_(packet), order_(order) {}
  std::uint8_t u8(std::size_t at) const { return p_[at]; }
  std::int8_t i8(std::size_t at) const { return static_cast<std::int8_t>(p_[at]); }
  std::uint16_t u16(std::size_t at) const { return static_cast<std::uint16_t>(bits(at, 2)); }
  std::uint32_t u32(std::size_t at) const { return static_cast<std::uint32_t>(bits(at, 4)); }
  float f32(std::size_t at) const { return std::bit_cast<float>(u32(at)); }
  double f64(std::size_t at) const { return std::bit_cast<double>(bits(at, 8)); }

 private:
  std::uint64_t bits(std::size_t at, std::size_t n) const {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t byte = order_ == ByteOrder::Big ? at + k : at + n - 1 - k;  // most significant first
      v = (v << 8) | p_[byte];
    }
    return v;
  }
  std::span<const std::uint8_t> p_;
  ByteOrder order_;
};

// Fields of one packet written into a zeroed block of its size, appended to a message.
class FieldWriter {
 public:
  FieldWriter(std::vector<std::uint8_t>& message, std::uint8_t opcode, std::uint8_t size, ByteOrder order)
      : m_(message), at_(message.size()), order_(order) {
    m_.resize(at_ + size, 0);
    m_[at_] = opcode;
    m_[at_ + 1] = size;
  }
  void u8(std::size_t at, std::uint8_t v) { m_[at_ + at] = v; }
  void i8(std::size_t at, std::int8_t v) { m_[at_ + at] = static_cast<std::uint8_t>(v); }
  void u16(std::size_t at, std::uint16_t v) { put(at, v, 2); }
  void u32(std::size_t at, std::uint32_t v) { put(at, v, 4); }
  void f32(std::size_t at, float v) { put(at, std::bit_cast<std::uint32_t>(v), 4); }
  void f64(std::size_t at, double v) { put(at, std::bit_cast<std::uint64_t>(v), 8); }
  // Sets bits of a byte (bit fields share bytes).
  void or_u8(std::size_t at, std::uint8_t v) { m_[at_ + at] |= v; }
  // Writes raw bytes (text).
  void bytes(std::size_t at, const void* data, std::size_t n) { std::memcpy(&m_[at_ + at], data, n); }

 private:
  void put(std::size_t at, std::uint64_t v, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t byte = order_ == ByteOrder::Big ? at_ + at + n - 1 - k : at_ + at + k;  // least significant first
      m_[byte] = static_cast<std::uint8_t>(v & 0xff);
      v >>= 8;
    }
  }
  std::vector<std::uint8_t>& m_;
  std::size_t at_;
  ByteOrder order_;
};

}  // namespace cloudsvc::cigi
