#include "service/frame_encoding.h"

#include <Imath/half.h>

#include "common/tone_map.h"

namespace cloudsvc {

std::vector<std::uint16_t> to_rgba16f(const FrameImage& img) {
  std::vector<std::uint16_t> out(img.rgba.size());
  for (std::size_t i = 0; i < img.rgba.size(); ++i) out[i] = imath_float_to_half(img.rgba[i]);
  return out;
}

std::vector<std::uint8_t> to_rgba8_srgb(const FrameImage& img) { return tone_map_srgb8(img.rgba, 4); }  // RGBA

}  // namespace cloudsvc
