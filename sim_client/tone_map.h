// Display images for people from the service's frame files: sweep --png and contact
// sheets. Linear radiance frames (EXR) are tone mapped by tone_map_display
// (common/tone_map.h), the recipe of the service's own PNG frames.
#pragma once

#include <string>
#include <vector>

namespace cloudsvc::sim {

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
