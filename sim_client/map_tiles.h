// A weather-map raster (e.g. read from an image) split into protocol WeatherMapTiles of at
// most max_side x max_side texels that together cover the raster's bounds exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "protocol/messages.h"
#include "sim_client/map_flags.h"

namespace cloudsvc::sim {

// Map values on an equirectangular grid over some bounds, in image order: row 0 is the
// NORTHERNMOST row, column 0 the westernmost. channel_bits[k] is the protocol tile_channel
// bit of value k of each texel, and the layer-coverage slots of layer_channels follow in
// ascending slot order: values[(row * width + col) * value_count() + k], all in [0, 1].
struct MapRaster {
  int width = 0, height = 0;               // texels
  std::vector<std::uint8_t> channel_bits;  // distinct tile_channel bits, in raster order
  std::uint8_t layer_channels = 0;         // WeatherMapTile.layer_channels bits (slots 0..3)
  std::vector<float> values;
  std::size_t value_count() const;         // values per texel
};

// Splits the raster into nx * ny tiles, nx = ceil(width / max_side), ny likewise, with
// column and row boundaries at floor(k * width / nx) (tiles of nearly equal size). Each
// tile's edges are the raster's texel edges: longitude lon_min + c * (lon_max - lon_min) /
// width (exactly lon_max at c = width) and likewise for latitude, so neighbouring tiles
// share edges bit for bit and the union is exactly `bounds`. Tile rows are flipped to the
// protocol's south-first order and the channels reordered into ascending bit order (the
// layer slots after them, as they are). A tile
// starting at or east of 180° is shifted by -360° (the protocol's lon_min is in
// [-180, 180)). Throws std::invalid_argument on an inconsistent raster or max_side < 1.
std::vector<protocol::WeatherMapTile> split_into_tiles(const MapRaster& raster, const GeoBounds& bounds,
                                                       double valid_at_utc_s, std::uint32_t max_side);

// The largest tile side (texels) allowed by a service's limits for `channels` values per
// texel: at most limits.max_tile_size, and small enough that a square tile's data fits in
// limits.max_payload_bytes with room for the message around it.
std::uint32_t tile_side_for(const protocol::Limits& limits, int channels);

}  // namespace cloudsvc::sim
