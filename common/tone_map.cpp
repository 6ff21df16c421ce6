// Display tone mapping (tone_map.h).
#include "common/tone_map.h"

#include <algorithm>
#include <cmath>

namespace cloudsvc {

namespace {

constexpr double kKey = 0.18;              // middle grey the log-average luminance maps to
constexpr double kMinExposure = 0.5;       // exposure factor limits: twilight (sky ~1e-5
constexpr double kMaxExposure = 5000.0;    // W m^-2 sr^-1 nm^-1) stays visible and dim, a
                                           // moonless night (airglow ~2e-9) stays black
constexpr double kIgnoreLuminance = 10.0;  // W m^-2 sr^-1 nm^-1: sun disk and glints
constexpr double kLogFloor = 1e-12;        // keeps log() finite for black pixels

double aces_filmic(double x) {  // Narkowicz 2015
  return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

double srgb_oetf(double v) {  // IEC 61966-2-1
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

std::size_t channels_of(int channels) { return static_cast<std::size_t>(std::max(channels, 3)); }

}  // namespace

double ToneMap::display(float radiance) const {
  const double x = std::isfinite(radiance) && radiance > 0.0f ? exposure * radiance : 0.0;
  return std::clamp(srgb_oetf(aces_filmic(x)), 0.0, 1.0);
}

ToneMap tone_map_for(std::span<const float> pixels, int channels, double exposure_ev) {
  const std::size_t nc = channels_of(channels);
  const std::size_t n = pixels.size() / nc;
  double log_sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = luminance(&pixels[i * nc]);
    if (std::isfinite(y) && y < kIgnoreLuminance) {
      log_sum += std::log(kLogFloor + std::max(y, 0.0));
      ++count;
    }
  }
  const double key = count ? std::exp(log_sum / static_cast<double>(count)) : 1.0;
  ToneMap t;
  t.exposure = std::clamp(kKey / key, kMinExposure, kMaxExposure) * std::exp2(exposure_ev);
  // A non-finite exposure_ev would make every pixel NaN x 0; the caller checks its range.
  if (!std::isfinite(t.exposure)) t.exposure = 0.0;
  return t;
}

std::vector<std::uint8_t> tone_map_srgb8(std::span<const float> pixels, int channels, double exposure_ev) {
  const std::size_t nc = channels_of(channels);
  const std::size_t n = pixels.size() / nc;
  const ToneMap t = tone_map_for(pixels, channels, exposure_ev);
  std::vector<std::uint8_t> out(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c)
      out[i * 4 + c] = static_cast<std::uint8_t>(std::lround(t.display(pixels[i * nc + c]) * 255.0));
    out[i * 4 + 3] = 255;
  }
  return out;
}

std::vector<float> tone_map_display(std::span<const float> pixels, int channels, double exposure_ev) {
  const std::size_t nc = channels_of(channels);
  const std::size_t n = pixels.size() / nc;
  const ToneMap t = tone_map_for(pixels, channels, exposure_ev);
  std::vector<float> out(pixels.size());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < nc; ++c)
      out[i * nc + c] = c < 3 ? static_cast<float>(t.display(pixels[i * nc + c])) : 1.0f;
  return out;
}

}  // namespace cloudsvc
