// Image error metrics (see image_metrics.h).
#include "renderer/reference/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cloudsvc::reference {

ImageDifference compare_images(const FrameImage& test, const FrameImage& reference, double fixed_peak) {
  if (test.width != reference.width || test.height != reference.height || test.rgba.size() != reference.rgba.size())
    throw std::invalid_argument("compare_images: sizes differ");
  ImageDifference d;
  double sum_sq = 0.0, sum_ref = 0.0, sum_sq_alpha = 0.0, peak = 0.0;
  const std::size_t pixels = static_cast<std::size_t>(test.width) * test.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double a = test.rgba[4 * i + c], b = reference.rgba[4 * i + c];
      const double e = a - b;
      sum_sq += e * e;
      sum_ref += b;
      peak = std::max(peak, b);
      if (std::abs(e) > d.max_error) {
        d.max_error = std::abs(e);
        d.max_error_x = static_cast<int>(i % static_cast<std::size_t>(test.width));
        d.max_error_y = static_cast<int>(i / static_cast<std::size_t>(test.width));
      }
    }
    const double ea = test.rgba[4 * i + 3] - reference.rgba[4 * i + 3];
    sum_sq_alpha += ea * ea;
  }
  const double n = 3.0 * static_cast<double>(pixels);
  const double mse = sum_sq / n;
  d.rmse = std::sqrt(mse);
  d.mean_reference = sum_ref / n;
  d.relative_rmse = d.mean_reference > 0.0 ? d.rmse / d.mean_reference : 0.0;
  d.peak = fixed_peak > 0.0 ? fixed_peak : peak;
  d.psnr_db = mse > 0.0 ? 10.0 * std::log10(d.peak * d.peak / mse) : std::numeric_limits<double>::infinity();
  d.opacity_rmse = std::sqrt(sum_sq_alpha / static_cast<double>(pixels));
  return d;
}

double cloud_pixel_fraction(const FrameImage& img) {
  const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
  std::size_t cloud = 0;
  for (std::size_t i = 0; i < pixels; ++i) cloud += img.rgba[4 * i + 3] > kCloudPixelOpacity ? 1 : 0;
  return pixels ? static_cast<double>(cloud) / static_cast<double>(pixels) : 0.0;
}

SilhouetteDifference compare_silhouettes(const FrameImage& test, const FrameImage& reference, int edge_radius_px) {
  if (test.width != reference.width || test.height != reference.height || test.rgba.size() != reference.rgba.size())
    throw std::invalid_argument("compare_silhouettes: sizes differ");
  const int w = reference.width, h = reference.height;
  const auto cloud = [](const FrameImage& img, int x, int y) { return img.pixel(x, y)[3] > kCloudPixelOpacity; };
  SilhouetteDifference d;
  double sum_sq = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool t = cloud(test, x, y), r = cloud(reference, x, y);
      d.test_cloud += t ? 1.0 : 0.0;
      d.reference_cloud += r ? 1.0 : 0.0;
      d.false_cloud += t && !r ? 1.0 : 0.0;
      d.missed_cloud += r && !t ? 1.0 : 0.0;
      bool any_cloud = false, any_clear = false;
      for (int j = std::max(0, y - edge_radius_px); j <= std::min(h - 1, y + edge_radius_px); ++j)
        for (int i = std::max(0, x - edge_radius_px); i <= std::min(w - 1, x + edge_radius_px); ++i)
          (cloud(reference, i, j) ? any_cloud : any_clear) = true;
      if (!(any_cloud && any_clear)) continue;
      ++d.edge_pixels;
      for (int c = 0; c < 3; ++c) {
        const double e = static_cast<double>(test.pixel(x, y)[c]) - reference.pixel(x, y)[c];
        sum_sq += e * e;
      }
    }
  const double pixels = static_cast<double>(w) * h;
  d.test_cloud /= pixels;
  d.reference_cloud /= pixels;
  d.false_cloud /= pixels;
  d.missed_cloud /= pixels;
  d.edge_rmse = d.edge_pixels ? std::sqrt(sum_sq / (3.0 * d.edge_pixels)) : 0.0;
  return d;
}

FrameImage box_downsample(const FrameImage& img, int n) {
  if (n <= 1) return img;
  FrameImage out;
  out.width = img.width / n;
  out.height = img.height / n;
  out.stats = img.stats;
  out.rgba.assign(static_cast<std::size_t>(out.width) * out.height * 4, 0.0f);
  const float k = 1.0f / static_cast<float>(n * n);
  for (int y = 0; y < out.height * n; ++y)
    for (int x = 0; x < out.width * n; ++x)
      for (int c = 0; c < 4; ++c)
        out.rgba[(static_cast<std::size_t>(y / n) * out.width + x / n) * 4 + c] += k * img.pixel(x, y)[c];
  return out;
}

}  // namespace cloudsvc::reference
