// Flag values of `sim_client weather --map` (cmd_weather.cpp): the map's geographic
// bounds and its channel list. Errors are cli::FlagError (common/option_values.h) naming
// the flag.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::sim {

// Geographic bounds of a weather map: "lat_min,lon_min,lat_max,lon_max", degrees.
struct GeoBounds {
  double lat_min_deg = 0.0, lon_min_deg = 0.0, lat_max_deg = 0.0, lon_max_deg = 0.0;
};
// lat in [-90, 90] with lat_min < lat_max; lon_min in [-180, 180), lon_max in
// (lon_min, lon_min + 360] (lon_max > 180 crosses the antimeridian, as in the protocol).
GeoBounds parse_flag_bounds(std::string_view flag, const std::string& text);

// Weather-map channel names in the order given ("coverage,density") -> protocol
// tile_channel bits, one per name. Names: coverage, development (or
// vertical-development), density, precipitation, albedo (the ground's); each at most once.
std::vector<std::uint8_t> parse_flag_channels(std::string_view flag, const std::string& text);
// The name of one tile_channel bit ("coverage", ...).
std::string channel_name(std::uint8_t bit);

}  // namespace cloudsvc::sim
