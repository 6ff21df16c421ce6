// The image metrics of renderer/reference/image_metrics.h that the benchmarks and the
// accuracy tests read, on images small enough to count by hand: the cloud-pixel fraction
// and the silhouette comparison (which pixels are cloud, the error on the cloud edges).
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/reference/image_metrics.h"

namespace cloudsvc::reference {
namespace {

// w x h pixels of radiance (rgb) 0 and opacity 0.
FrameImage clear_image(int w, int h) {
  FrameImage img;
  img.width = w;
  img.height = h;
  img.rgba.assign(static_cast<std::size_t>(w) * h * 4, 0.0f);
  return img;
}

void set(FrameImage& img, int x, int y, float radiance, float opacity) {
  float* p = &img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4];
  p[0] = p[1] = p[2] = radiance;
  p[3] = opacity;
}

TEST(ImageMetrics, CloudPixelsAreThoseAboveTheOpacityThreshold) {
  FrameImage img = clear_image(4, 2);
  set(img, 0, 0, 0.0f, static_cast<float>(kCloudPixelOpacity));  // at the threshold: clear
  set(img, 1, 0, 0.0f, 0.02f);
  set(img, 2, 1, 0.0f, 1.0f);
  EXPECT_DOUBLE_EQ(cloud_pixel_fraction(img), 2.0 / 8.0);
}

// A 2 x 2 cloud in a 10 x 10 image, and the same cloud dilated by one pixel on each side
// (a 4 x 4 block): 12 false cloud pixels, none missed; the edge band of radius 1 around the
// reference's silhouette is the 4 x 4 block (its 12 clear pixels and the 4 cloud pixels
// they touch), so with radiance 1 on every dilated pixel and the reference's cloud exact,
// the edge RMSE is sqrt(12 / 16).
TEST(ImageMetrics, ADilatedSilhouetteShowsAsFalseCloudOnTheEdgeBand) {
  FrameImage ref = clear_image(10, 10), dilated = clear_image(10, 10);
  for (int y = 4; y < 6; ++y)
    for (int x = 4; x < 6; ++x) set(ref, x, y, 1.0f, 1.0f);
  for (int y = 3; y < 7; ++y)
    for (int x = 3; x < 7; ++x) set(dilated, x, y, 1.0f, 0.5f);
  const SilhouetteDifference d = compare_silhouettes(dilated, ref, 1);
  EXPECT_DOUBLE_EQ(d.reference_cloud, 0.04);
  EXPECT_DOUBLE_EQ(d.test_cloud, 0.16);
  EXPECT_DOUBLE_EQ(d.false_cloud, 0.12);
  EXPECT_DOUBLE_EQ(d.missed_cloud, 0.0);
  EXPECT_EQ(d.edge_pixels, 16);
  EXPECT_NEAR(d.edge_rmse, std::sqrt(12.0 / 16.0), 1e-12);
  // the other way round: every pixel of the dilated block's inside is cloud in both
  const SilhouetteDifference e = compare_silhouettes(ref, dilated, 1);
  EXPECT_DOUBLE_EQ(e.missed_cloud, 0.12);
  EXPECT_DOUBLE_EQ(e.false_cloud, 0.0);
  // the band of radius 2 holds the 6 x 6 block around the reference's 2 x 2 cloud
  EXPECT_EQ(compare_silhouettes(dilated, ref, 2).edge_pixels, 36);
  // an image against itself
  const SilhouetteDifference s = compare_silhouettes(ref, ref);
  EXPECT_DOUBLE_EQ(s.false_cloud + s.missed_cloud, 0.0);
  EXPECT_DOUBLE_EQ(s.edge_rmse, 0.0);
}

}  // namespace
}  // namespace cloudsvc::reference
