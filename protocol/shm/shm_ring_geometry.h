// Checks of the sizes a shared-memory frame ring declares (protocol/shm/shm_layout.h) against
// the segment a reader actually mapped. The header and slot headers live in memory another
// process writes, so a reader trusts none of their sizes: every product and sum is computed
// with overflow checks, and a reader keeps a checked copy of the ring's geometry (taken once
// at open) instead of re-reading the header's sizes on every frame.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "protocol/shm/shm_layout.h"

namespace cloudsvc {

// The ring's sizes, checked: slot i (i < slot_count) lies entirely inside the mapping, its
// pixels at most pixel_capacity bytes.
struct RingGeometry {
  std::uint32_t header_bytes = 0;    // offset of slot 0, bytes
  std::uint32_t slot_count = 0;
  std::uint64_t slot_stride = 0;     // bytes from one slot to the next
  std::uint32_t max_width = 0;       // pixels
  std::uint32_t max_height = 0;
  std::uint64_t pixel_capacity = 0;  // slot_stride - CLOUDSVC_SHM_SLOT_HEADER_BYTES, bytes

  // Byte offset of slot i from the start of the segment (i < slot_count).
  std::uint64_t slot_offset(std::uint32_t i) const { return header_bytes + slot_stride * i; }
};

// The geometry of header `h` in a segment of mapped_bytes bytes, or the problem naming the
// field: "slot_stride 9223372036854775808 x slot_count 2 overflows 64 bits". Checks magic
// and version, then: header_bytes >= sizeof(cloudsvc_shm_header) and a multiple of 8 (the
// slot header's alignment, for its atomic seq); slot_count >= 1; slot_stride >= the
// 256-byte slot header and a multiple of 8; max_width, max_height >= 1 with
// max_width x max_height x 8 (RGBA16F, the larger format) <= the pixel capacity of a slot;
// header_bytes + slot_count x slot_stride <= mapped_bytes.
std::optional<std::string> ring_geometry_problem(const cloudsvc_shm_header& h, std::uint64_t mapped_bytes,
                                                 RingGeometry& out);

// Bytes per pixel of a slot's pixel_format: 8 (RGBA16F linear), 4 (RGBA8 sRGB), 0 unknown.
std::uint32_t shm_bytes_per_pixel(std::uint32_t pixel_format);

// The problem with slot header `s` in ring `g`, naming the field, or nullopt: pixel_format
// known; 1 <= width <= max_width, 1 <= height <= max_height; row_bytes >= width x bytes per
// pixel; pixel_bytes == row_bytes x height; pixel_bytes <= the slot's pixel capacity.
std::optional<std::string> slot_problem(const cloudsvc_shm_slot& s, const RingGeometry& g);

}  // namespace cloudsvc
