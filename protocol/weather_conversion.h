// Conversions between the protocol's weather messages and the weather module's types
// (shared by the service and sim_client; the protocol library links the pure weather module).
#pragma once

#include "protocol/messages.h"
#include "weather/cloud_layer.h"
#include "weather/weather_timeline.h"

namespace cloudsvc {

weather::Weather to_weather(const protocol::WeatherLayers& m);
protocol::WeatherLayers to_message(const weather::Weather& w);
weather::MapTile to_map_tile(const protocol::WeatherMapTile& m);
// The tile's fields but its values, sizes as sent: what weather::tile_header_problem() and
// tile_data_problem() judge (protocol/validate.cpp).
weather::MapTileHeader to_tile_header(const protocol::WeatherMapTile& m);
protocol::WeatherMapTile to_message(const weather::MapTile& t);

}  // namespace cloudsvc
