// Small weather-map images for the seed corpus of the simclient_map_image fuzz target
// (make_seeds.cpp), one or more per format that target sends to OpenImageIO: OpenEXR,
// PNG, TIFF, Radiance HDR, PNM and PFM, with 1 to 4 channels, 8/16-bit and float pixels,
// and values outside [0, 1] and NaN for the error paths.
#pragma once

#include <filesystem>

namespace cloudsvc::fuzz {

// Writes the images into dir (which exists); throws std::runtime_error if one cannot be
// written.
void write_seed_images(const std::filesystem::path& dir);

}  // namespace cloudsvc::fuzz
