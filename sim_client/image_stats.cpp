// Frame statistics (image_stats.h).
#include "sim_client/image_stats.h"

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <stdexcept>

namespace cloudsvc::sim {

ImageStats compute_image_stats(const std::vector<float>& pixels, int width, int height, int channels) {
  if (width < 1 || height < 1 || channels < 3)
    throw std::invalid_argument("image statistics need at least 1x1 pixels with R, G, B");
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (pixels.size() != n * static_cast<std::size_t>(channels))
    throw std::invalid_argument("image statistics: pixel buffer size does not match width x height x channels");
  ImageStats s;
  s.width = width;
  s.height = height;
  s.has_alpha = channels >= 4;
  double luminance_sum = 0.0;  // W m^-2 sr^-1 nm^-1 summed over finite pixels
  std::size_t finite = 0, cloud = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const float* p = &pixels[i * static_cast<std::size_t>(channels)];
    bool ok = true;
    for (int c = 0; c < channels; ++c) ok = ok && std::isfinite(p[c]);
    if (!ok) {
      ++s.nonfinite;
      continue;
    }
    luminance_sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    ++finite;
    if (s.has_alpha && p[3] > kCloudAlpha) ++cloud;
  }
  s.mean_radiance = finite ? luminance_sum / static_cast<double>(finite) : 0.0;
  s.cloud_fraction = static_cast<double>(cloud) / static_cast<double>(n);
  return s;
}

ImageStats read_image_stats(const std::string& path) {
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw std::runtime_error(path + ": cannot read image: " + buf.geterror());
  const OIIO::ImageSpec& spec = buf.spec();
  if (spec.nchannels < 3) throw std::runtime_error(path + ": image has " + std::to_string(spec.nchannels) + " channels, need R, G, B");
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!buf.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, px.data()))
    throw std::runtime_error(path + ": cannot read pixels: " + buf.geterror());
  return compute_image_stats(px, spec.width, spec.height, spec.nchannels);
}

}  // namespace cloudsvc::sim
