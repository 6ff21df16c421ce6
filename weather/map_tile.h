// A weather-map tile (a georeferenced patch of some channels of the global weather map)
// and the one set of rules a tile must satisfy. Every path a tile takes is checked with
// these rules: the protocol checks a WeatherMapTile with them (protocol/validate.cpp adds
// only its UTC range), and the timeline and the renderer expect tiles without a problem()
// (CloudRenderer::apply_tile checks).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::weather {

// Largest tile width or height, texels. 1024 x 1024 x 5 channels x 4 bytes is 20 MiB;
// larger areas are sent as several tiles. The protocol's limit (protocol::kMaxTileSize,
// announced in Welcome) is this constant.
inline constexpr int kMaxTileTexels = 1024;

// Channel bits of a tile: bit 0 coverage (R), 1 cloud type (G; "vertical development" in
// the protocol), 2 density (B), 3 precipitation (A) of the weather map; bit 4 the ground's
// albedo (weather/ground_albedo_map.h, not part of the weather map). Values are
// interleaved per texel in ascending bit order.
inline constexpr std::uint8_t kWeatherMapTileChannels = 0x0f;
inline constexpr std::uint8_t kGroundAlbedoTileChannel = 0x10;
inline constexpr std::uint8_t kAllTileChannels = kWeatherMapTileChannels | kGroundAlbedoTileChannel;

// Layer-coverage slot bits of a tile (MapTile::layer_channels): bit k is slot k of the
// weather map's layer coverage (WeatherMap::layer_coverage), the coverage [0, 1] of the
// layers whose CloudLayer::coverage_channel is k (forecast weather). A tile's values of these
// slots follow the values of its `channels` in each texel, in ascending slot order.
inline constexpr std::uint8_t kAllLayerCoverageSlots = 0x0f;

// A tile's fields but its values, as the rules read them; the sizes are 64-bit so that a
// message's (unsigned 32-bit) sizes are judged as they were sent.
struct MapTileHeader {
  double lat_min_deg = 0.0, lon_min_deg = 0.0, lat_max_deg = 0.0, lon_max_deg = 0.0;
  std::int64_t width = 0, height = 0;
  std::uint8_t channels = 0;
  double valid_at_utc_s = 0.0;
  std::uint8_t layer_channels = 0;
};

// Values per texel of a tile with these channel and layer-coverage slot bits.
int tile_value_count(std::uint8_t channels, std::uint8_t layer_channels);

struct MapTile {
  double lat_min_deg = 0.0, lon_min_deg = 0.0;  // south-west corner
  double lat_max_deg = 0.0, lon_max_deg = 0.0;  // north-east corner; lon_max may exceed 180 (wraps)
  int width = 0, height = 0;                    // texels; row 0 at the south
  std::uint8_t channels = 0;        // kAllTileChannels bits
  double valid_at_utc_s = 0.0;
  std::uint8_t layer_channels = 0;  // kAllLayerCoverageSlots bits
  std::vector<float> data;          // height * width * tile_value_count(channels, layer_channels)

  MapTileHeader header() const;
  // The first rule the tile breaks, as one line naming the field after `field_prefix`
  // (the protocol passes "WeatherMapTile.": "WeatherMapTile.lat_min_deg -91 out of range
  // [-90, 90)"); empty when the tile is usable. tile_header_problem(), then
  // tile_data_problem().
  std::string problem(std::string_view field_prefix = "MapTile.") const;
};

// The rules of a tile's fields, in the order checked: lat_min_deg in [-90, 90),
// lat_max_deg in (lat_min_deg, 90], lon_min_deg in [-180, 180), lon_max_deg in
// (lon_min_deg, lon_min_deg + 360], width and height in [1, kMaxTileTexels], channels a
// subset of kAllTileChannels, layer_channels a subset of kAllLayerCoverageSlots, not both
// empty, valid_at_utc_s finite. Empty when all hold.
std::string tile_header_problem(const MapTileHeader& tile, std::string_view field_prefix);

// The rules of a tile's values, for a header without a problem: width * height *
// tile_value_count of them, each in [0, 1] (a bad one is named by index, column, row and channel).
// Separate from the header's so that the protocol checks a message's values where they
// are, without copying (up to 16 MiB of) them into a MapTile.
std::string tile_data_problem(const MapTileHeader& tile, std::span<const float> values,
                              std::string_view field_prefix);

}  // namespace cloudsvc::weather
