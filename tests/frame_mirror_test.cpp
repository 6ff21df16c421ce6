// Mirrored views (service/frame_mirror.h): CIGI's mirror modes flip a frame left-right,
// top-bottom or both, pixels and standard errors alike.
#include <gtest/gtest.h>

#include "service/frame_mirror.h"

namespace cloudsvc {
namespace {

// A w x h image whose pixel (x, y) holds (x, y, 10 x + y, 1) and standard errors (x, y, -1).
FrameImage numbered(int w, int h) {
  FrameImage img;
  img.width = w;
  img.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.rgba.insert(img.rgba.end(), {float(x), float(y), float(10 * x + y), 1.0f});
      img.std_error.insert(img.std_error.end(), {float(x), float(y), -1.0f});
    }
  img.stats.cloud_pixels = 42;
  return img;
}

// Where pixel (x, y) of the mirrored image came from.
void expect_pixels_from(const FrameImage& img, bool left_right, bool top_bottom) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int sx = left_right ? img.width - 1 - x : x, sy = top_bottom ? img.height - 1 - y : y;
      const float* p = img.pixel(x, y);
      EXPECT_EQ(p[0], sx) << x << "," << y;
      EXPECT_EQ(p[1], sy) << x << "," << y;
      EXPECT_EQ(p[2], 10 * sx + sy);
      EXPECT_EQ(p[3], 1.0f);
      const float* e = &img.std_error[(static_cast<std::size_t>(y) * img.width + x) * 3];
      EXPECT_EQ(e[0], sx);
      EXPECT_EQ(e[1], sy);
      EXPECT_EQ(e[2], -1.0f);
    }
}

TEST(FrameMirror, EachModeFlipsTheWayCigiSays) {
  for (const auto& [w, h] : {std::pair{5, 3}, std::pair{4, 4}, std::pair{1, 2}, std::pair{7, 1}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    FrameImage img = numbered(w, h);
    mirror_image(img, MirrorMode::None);
    expect_pixels_from(img, false, false);
    img = numbered(w, h);
    mirror_image(img, MirrorMode::Horizontal);
    expect_pixels_from(img, true, false);
    img = numbered(w, h);
    mirror_image(img, MirrorMode::Vertical);
    expect_pixels_from(img, false, true);
    img = numbered(w, h);
    mirror_image(img, MirrorMode::Both);
    expect_pixels_from(img, true, true);
    EXPECT_EQ(img.stats.cloud_pixels, 42) << "the statistics are the image's";
    // twice is none
    mirror_image(img, MirrorMode::Both);
    expect_pixels_from(img, false, false);
  }
}

TEST(FrameMirror, AnImageWithoutStandardErrorsFlipsItsPixels) {
  FrameImage img = numbered(3, 2);
  img.std_error.clear();
  mirror_image(img, MirrorMode::Horizontal);
  EXPECT_TRUE(img.std_error.empty());
  EXPECT_EQ(img.pixel(0, 0)[0], 2.0f);
  EXPECT_EQ(img.pixel(2, 1)[0], 0.0f);
}

}  // namespace
}  // namespace cloudsvc
