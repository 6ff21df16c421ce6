// Reads a weather-map image (any format OpenImageIO reads: EXR, TIFF, PNG, ...) into a
// MapRaster: the image's first N channels become the N listed map channels, in order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim_client/map_tiles.h"

namespace cloudsvc::sim {

// channel_bits: protocol tile_channel bits, one per image channel used (parse_flag_channels).
// Values are read as float (8- and 16-bit integer images scale to [0, 1]); the image's top
// row is the northern edge. Throws UsageError (usage_errors.h) naming the file when it cannot
// be read, has fewer channels than listed, or a value is not finite or outside [0, 1]:
//   "map.exr: pixel (x 12, y 40) channel 1 (density): value 1.5 outside [0, 1]"
// (x counted from the west edge, y from the top/north edge, channels from 0).
MapRaster read_map_image(const std::string& path, const std::vector<std::uint8_t>& channel_bits);

// The same checks on values already in memory (image order, interleaved); `source` names
// them in the message.
void check_map_values(const MapRaster& raster, const std::string& source);

}  // namespace cloudsvc::sim
