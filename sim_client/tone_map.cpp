// Display conversion of linear frames (tone_map.h).
#include "sim_client/tone_map.h"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cloudsvc::sim {

namespace {

constexpr double kKey = 0.18;               // middle grey the log-average luminance maps to
constexpr double kMinExposure = 0.5;        // exposure factor limits: night stays dark
constexpr double kMaxExposure = 5000.0;
constexpr double kIgnoreLuminance = 10.0;   // W m^-2 sr^-1 nm^-1: sun disk and glints

double aces_filmic(double x) {  // Narkowicz 2015
  return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

double srgb_oetf(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

}  // namespace

std::vector<float> tone_map_display(const std::vector<float>& px, int channels) {
  const std::size_t nc = static_cast<std::size_t>(std::max(channels, 3));
  const std::size_t n = px.size() / nc;
  double log_sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = luminance(&px[i * nc]);
    if (std::isfinite(y) && y < kIgnoreLuminance) {
      log_sum += std::log(1e-12 + std::max(y, 0.0));
      ++count;
    }
  }
  const double key = count ? std::exp(log_sum / static_cast<double>(count)) : 1.0;
  const double exposure = std::clamp(kKey / key, kMinExposure, kMaxExposure);
  std::vector<float> out(px.size());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < nc; ++c) {
      const float v = px[i * nc + c];
      out[i * nc + c] = c >= 3 ? 1.0f
                               : static_cast<float>(srgb_oetf(aces_filmic(exposure * (std::isfinite(v) ? std::max(0.0f, v) : 0.0f))));
    }
  return out;
}

DisplayImage read_display_image(const std::string& path) {
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw std::runtime_error(path + ": cannot read image: " + buf.geterror());
  const OIIO::ImageSpec& spec = buf.spec();
  if (spec.nchannels < 3) throw std::runtime_error(path + ": need an RGB image");
  const OIIO::TypeDesc stored = buf.nativespec().format;  // the pixel type in the file
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!buf.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, px.data()))
    throw std::runtime_error(path + ": cannot read pixels: " + buf.geterror());
  const bool linear = stored.basetype == OIIO::TypeDesc::HALF || stored.basetype == OIIO::TypeDesc::FLOAT ||
                      stored.basetype == OIIO::TypeDesc::DOUBLE;
  if (linear) px = tone_map_display(px, spec.nchannels);
  DisplayImage img;
  img.width = spec.width;
  img.height = spec.height;
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for (std::size_t i = 0; i < img.rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c)
      img.rgb[i * 3 + c] = std::clamp(px[i * spec.nchannels + c], 0.0f, 1.0f);
  return img;
}

void write_display_png(const std::string& path, const DisplayImage& img) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT),
                     const_cast<float*>(img.rgb.data()));
  if (!buf.write(path, OIIO::TypeDesc::UINT8)) throw std::runtime_error(path + ": cannot write: " + buf.geterror());
}

}  // namespace cloudsvc::sim
