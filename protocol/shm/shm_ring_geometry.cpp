// Overflow-safe checks of a frame ring's declared sizes (shm_ring_geometry.h).
#include "protocol/shm/shm_ring_geometry.h"

namespace cloudsvc {

namespace {

std::string num(std::uint64_t v) { return std::to_string(v); }

// The slot header's alignment: `seq` is read with std::atomic_ref, which needs it.
constexpr std::uint64_t kSlotAlignment = alignof(cloudsvc_shm_slot);
// Bytes per pixel of the larger pixel format (RGBA16F): what the writer sizes slots for.
constexpr std::uint64_t kMaxBytesPerPixel = 8;

}  // namespace

std::optional<std::string> ring_geometry_problem(const cloudsvc_shm_header& h, std::uint64_t mapped_bytes,
                                                 RingGeometry& out) {
  if (h.magic != CLOUDSVC_SHM_MAGIC) return "not a cloudsvc frame ring (bad magic)";
  if (h.version != CLOUDSVC_SHM_VERSION)
    return "unsupported ring version " + num(h.version) + " (this reader reads version " + num(CLOUDSVC_SHM_VERSION) + ")";
  if (h.header_bytes < sizeof(cloudsvc_shm_header))
    return "header_bytes " + num(h.header_bytes) + " puts slot 0 inside the " + num(sizeof(cloudsvc_shm_header)) +
           "-byte ring header";
  if (h.header_bytes % kSlotAlignment != 0)
    return "header_bytes " + num(h.header_bytes) + " is not a multiple of 8 (slot alignment)";
  if (h.slot_count == 0) return "slot_count 0: a ring without slots";
  if (h.slot_stride < CLOUDSVC_SHM_SLOT_HEADER_BYTES)
    return "slot_stride " + num(h.slot_stride) + " is smaller than the " + num(CLOUDSVC_SHM_SLOT_HEADER_BYTES) +
           "-byte slot header";
  if (h.slot_stride % kSlotAlignment != 0)
    return "slot_stride " + num(h.slot_stride) + " is not a multiple of 8 (slot alignment)";
  std::uint64_t slots_bytes = 0, ring_bytes = 0;
  if (__builtin_mul_overflow(h.slot_stride, std::uint64_t{h.slot_count}, &slots_bytes))
    return "slot_stride " + num(h.slot_stride) + " x slot_count " + num(h.slot_count) + " overflows 64 bits";
  if (__builtin_add_overflow(std::uint64_t{h.header_bytes}, slots_bytes, &ring_bytes))
    return "header_bytes " + num(h.header_bytes) + " + slot_count " + num(h.slot_count) + " x slot_stride " +
           num(h.slot_stride) + " overflows 64 bits";
  if (ring_bytes > mapped_bytes)
    return "header_bytes " + num(h.header_bytes) + " + slot_count " + num(h.slot_count) + " x slot_stride " +
           num(h.slot_stride) + " = " + num(ring_bytes) + " bytes, larger than the " + num(mapped_bytes) +
           "-byte segment";
  if (h.max_width == 0) return "max_width 0";
  if (h.max_height == 0) return "max_height 0";
  const std::uint64_t capacity = h.slot_stride - CLOUDSVC_SHM_SLOT_HEADER_BYTES;
  std::uint64_t max_pixels = 0, max_frame_bytes = 0;
  if (__builtin_mul_overflow(std::uint64_t{h.max_width}, std::uint64_t{h.max_height}, &max_pixels) ||
      __builtin_mul_overflow(max_pixels, kMaxBytesPerPixel, &max_frame_bytes))
    return "max_width " + num(h.max_width) + " x max_height " + num(h.max_height) + " x 8 bytes overflows 64 bits";
  if (max_frame_bytes > capacity)
    return "max_width " + num(h.max_width) + " x max_height " + num(h.max_height) + " x 8 bytes = " +
           num(max_frame_bytes) + " does not fit a slot's " + num(capacity) + " pixel bytes";
  out.header_bytes = h.header_bytes;
  out.slot_count = h.slot_count;
  out.slot_stride = h.slot_stride;
  out.max_width = h.max_width;
  out.max_height = h.max_height;
  out.pixel_capacity = capacity;
  return std::nullopt;
}

std::uint32_t shm_bytes_per_pixel(std::uint32_t pixel_format) {
  switch (pixel_format) {
    case CLOUDSVC_SHM_RGBA16F_LINEAR: return 8;
    case CLOUDSVC_SHM_RGBA8_SRGB: return 4;
    default: return 0;
  }
}

std::optional<std::string> slot_problem(const cloudsvc_shm_slot& s, const RingGeometry& g) {
  const std::uint32_t bpp = shm_bytes_per_pixel(s.pixel_format);
  if (bpp == 0)
    return "pixel_format " + num(s.pixel_format) + " unknown (0 RGBA16F linear, 1 RGBA8 sRGB)";
  if (s.width == 0 || s.width > g.max_width)
    return "width " + num(s.width) + " outside [1, max_width " + num(g.max_width) + "]";
  if (s.height == 0 || s.height > g.max_height)
    return "height " + num(s.height) + " outside [1, max_height " + num(g.max_height) + "]";
  const std::uint64_t min_row = std::uint64_t{s.width} * bpp;  // < 2^35: no overflow
  if (s.row_bytes < min_row)
    return "row_bytes " + num(s.row_bytes) + " shorter than width " + num(s.width) + " x " + num(bpp) +
           " bytes per pixel = " + num(min_row);
  std::uint64_t rows_bytes = 0;
  if (__builtin_mul_overflow(std::uint64_t{s.row_bytes}, std::uint64_t{s.height}, &rows_bytes) ||
      s.pixel_bytes != rows_bytes)
    return "pixel_bytes " + num(s.pixel_bytes) + " is not row_bytes " + num(s.row_bytes) + " x height " +
           num(s.height);
  if (s.pixel_bytes > g.pixel_capacity)
    return "pixel_bytes " + num(s.pixel_bytes) + " exceed the slot's " + num(g.pixel_capacity) + " pixel bytes";
  return std::nullopt;
}

}  // namespace cloudsvc
