#include "protocol/weather_conversion.h"

namespace cloudsvc {

weather::Weather to_weather(const protocol::WeatherLayers& m) {
  weather::Weather w;
  w.name = "protocol";
  w.map_seed = m.map_seed;
  w.ground_albedo = m.ground_albedo;
  w.visibility_m = m.visibility_m;
  for (const protocol::CloudLayer& l : m.layers) {
    weather::CloudLayer c;
    c.type = static_cast<weather::CloudType>(l.type);
    c.base_m = l.base_m;
    c.top_m = l.top_m;
    c.coverage = l.coverage;
    c.density_scale = l.density_scale;
    c.droplet_diameter_um = l.droplet_diameter_um;
    c.wind = {l.wind_east_mps, l.wind_north_mps};
    c.coverage_channel = l.coverage_channel;
    w.layers.push_back(c);
  }
  return w;
}

protocol::WeatherLayers to_message(const weather::Weather& w) {
  protocol::WeatherLayers m;
  m.map_seed = w.map_seed;
  m.ground_albedo = w.ground_albedo;
  m.visibility_m = w.visibility_m;
  for (const weather::CloudLayer& c : w.layers) {
    protocol::CloudLayer l;
    l.type = static_cast<std::uint8_t>(c.type);
    l.base_m = c.base_m;
    l.top_m = c.top_m;
    l.coverage = c.coverage;
    l.density_scale = c.density_scale;
    l.droplet_diameter_um = c.droplet_diameter_um;
    l.wind_east_mps = c.wind.east_mps;
    l.wind_north_mps = c.wind.north_mps;
    l.coverage_channel = static_cast<std::int8_t>(c.coverage_channel);
    m.layers.push_back(l);
  }
  return m;
}

weather::MapTile to_map_tile(const protocol::WeatherMapTile& m) {
  weather::MapTile t;
  t.lat_min_deg = m.lat_min_deg;
  t.lon_min_deg = m.lon_min_deg;
  t.lat_max_deg = m.lat_max_deg;
  t.lon_max_deg = m.lon_max_deg;
  t.width = static_cast<int>(m.width);
  t.height = static_cast<int>(m.height);
  t.channels = m.channels;
  t.valid_at_utc_s = m.valid_at_utc_s;
  t.layer_channels = m.layer_channels;
  t.data = m.data;
  return t;
}

weather::MapTileHeader to_tile_header(const protocol::WeatherMapTile& m) {
  return weather::MapTileHeader{m.lat_min_deg, m.lon_min_deg, m.lat_max_deg, m.lon_max_deg,
                                m.width,       m.height,      m.channels,    m.valid_at_utc_s,
                                m.layer_channels};
}

protocol::WeatherMapTile to_message(const weather::MapTile& t) {
  protocol::WeatherMapTile m;
  m.lat_min_deg = t.lat_min_deg;
  m.lon_min_deg = t.lon_min_deg;
  m.lat_max_deg = t.lat_max_deg;
  m.lon_max_deg = t.lon_max_deg;
  m.width = static_cast<std::uint32_t>(t.width);
  m.height = static_cast<std::uint32_t>(t.height);
  m.channels = t.channels;
  m.valid_at_utc_s = t.valid_at_utc_s;
  m.layer_channels = t.layer_channels;
  m.data = t.data;
  return m;
}

}  // namespace cloudsvc
