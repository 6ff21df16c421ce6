#include "protocol/utf8.h"

#include <cstdint>

namespace cloudsvc::protocol {

bool is_valid_utf8(std::string_view s) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(s.data());
  const std::size_t n = s.size();
  std::size_t i = 0;
  while (i < n) {
    const std::uint8_t b = p[i];
    if (b < 0x80) {
      ++i;
      continue;
    }
    // Lead byte: sequence length and the smallest code point it may encode.
    int extra = 0;
    std::uint32_t cp = 0;
    std::uint32_t min_cp = 0;
    if ((b & 0xe0) == 0xc0) {
      extra = 1, cp = b & 0x1f, min_cp = 0x80;
    } else if ((b & 0xf0) == 0xe0) {
      extra = 2, cp = b & 0x0f, min_cp = 0x800;
    } else if ((b & 0xf8) == 0xf0) {
      extra = 3, cp = b & 0x07, min_cp = 0x10000;
    } else {
      return false;  // continuation byte without a lead, or 0xf8..0xff
    }
    if (n - i <= static_cast<std::size_t>(extra)) return false;
    for (int k = 1; k <= extra; ++k) {
      const std::uint8_t c = p[i + k];
      if ((c & 0xc0) != 0x80) return false;
      cp = (cp << 6) | (c & 0x3f);
    }
    if (cp < min_cp || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return false;
    i += 1 + extra;
  }
  return true;
}

}  // namespace cloudsvc::protocol
