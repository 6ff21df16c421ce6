// Display conversion of the service's linear radiance frames (EXR) for people: sweep --png
// and contact sheets. Same recipe as the service's own PNG frames: auto exposure from the
// log-average luminance (key 0.18, exposure factor clamped to [0.5, 5000], pixels with
// luminance >= 10 such as the sun disk ignored), the ACES filmic fit of Narkowicz 2015 and
// the sRGB transfer function.
#pragma once

#include <string>
#include <vector>

namespace cloudsvc::sim {

// rgb: interleaved linear values (W m^-2 sr^-1 nm^-1), `channels` per pixel (>= 3);
// returns display values in [0, 1] (sRGB-encoded), same layout; alpha channels become 1.
// Non-finite values become 0.
std::vector<float> tone_map_display(const std::vector<float>& rgb, int channels);

// Reads an image; a floating-point one (EXR, HDR) is tone mapped, an integer one (PNG) is
// taken as display-ready. Returns RGB display values in [0, 1], 3 per pixel. Throws
// std::runtime_error naming the file when it cannot be read.
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
};
DisplayImage read_display_image(const std::string& path);

// Writes an 8-bit sRGB PNG (RGB). Throws std::runtime_error naming the path on failure.
void write_display_png(const std::string& path, const DisplayImage& img);

}  // namespace cloudsvc::sim
