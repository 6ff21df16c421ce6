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
