// Statistics of a rendered frame for sweeps: mean radiance, cloud fraction, bad values.
// Meant for the service's EXR frames (linear radiance in W m^-2 sr^-1 nm^-1 at
// 680/550/440 nm as R/G/B, A = cloud opacity; docs/PROTOCOL.md, file sink).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cloudsvc::sim {

struct ImageStats {
  int width = 0, height = 0;  // pixels
  // Mean over the finite pixels of the luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the
  // linear values (W m^-2 sr^-1 nm^-1 for the service's EXR); 0 when no pixel is finite.
  double mean_radiance = 0.0;
  // Fraction of all pixels whose alpha (cloud opacity) exceeds kCloudAlpha; 0 when the
  // image has no alpha channel (has_alpha false).
  double cloud_fraction = 0.0;
  bool has_alpha = false;
  // Pixels with at least one NaN or infinite channel value.
  std::size_t nonfinite = 0;
};

inline constexpr float kCloudAlpha = 0.01f;  // opacity above which a pixel counts as cloud

// From interleaved float pixels: width * height * channels values, channels >= 3 (R, G, B
// first; channel 3, if present, is alpha). Throws std::invalid_argument on a size mismatch.
ImageStats compute_image_stats(const std::vector<float>& pixels, int width, int height, int channels);

// Reads an image with OpenImageIO (as float) and computes its statistics. Throws
// std::runtime_error naming the file when it cannot be read or has fewer than 3 channels.
ImageStats read_image_stats(const std::string& path);

}  // namespace cloudsvc::sim
