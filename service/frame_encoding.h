// Pixel formats of the frame sinks: linear RGBA16F (IEEE half) and tone-mapped sRGB RGBA8,
// both rows top first.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc {

std::vector<std::uint16_t> to_rgba16f(const FrameImage& img);  // width*height*4 halves
std::vector<std::uint8_t> to_rgba8_srgb(const FrameImage& img);  // width*height*4 bytes

}  // namespace cloudsvc
