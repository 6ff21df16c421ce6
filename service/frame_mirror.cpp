// Mirrored views (frame_mirror.h).
#include "service/frame_mirror.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace cloudsvc {
namespace {

// Flip a width x height image of `channels` floats per pixel, rows from the top.
void flip(std::vector<float>& px, int width, int height, std::size_t channels, bool left_right, bool top_bottom) {
  if (px.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * channels) return;
  const std::size_t row = static_cast<std::size_t>(width) * channels;
  if (left_right)
    for (int y = 0; y < height; ++y)
      for (int a = 0, b = width - 1; a < b; ++a, --b)
        std::swap_ranges(px.begin() + static_cast<std::ptrdiff_t>(y * row + a * channels),
                         px.begin() + static_cast<std::ptrdiff_t>(y * row + (a + 1) * channels),
                         px.begin() + static_cast<std::ptrdiff_t>(y * row + b * channels));
  if (top_bottom)
    for (int a = 0, b = height - 1; a < b; ++a, --b)
      std::swap_ranges(px.begin() + static_cast<std::ptrdiff_t>(a * row), px.begin() + static_cast<std::ptrdiff_t>((a + 1) * row),
                       px.begin() + static_cast<std::ptrdiff_t>(b * row));
}

}  // namespace

void mirror_image(FrameImage& img, MirrorMode mode) {
  const bool lr = mode == MirrorMode::Horizontal || mode == MirrorMode::Both;
  const bool tb = mode == MirrorMode::Vertical || mode == MirrorMode::Both;
  if (!lr && !tb) return;
  flip(img.rgba, img.width, img.height, 4, lr, tb);
  flip(img.std_error, img.width, img.height, 3, lr, tb);
}

}  // namespace cloudsvc
