// The ground's albedo where weather-map tiles set it (the tile channel
// kGroundAlbedoTileChannel, weather/map_tile.h): grey Lambertian albedo in [0, 1] on the
// weather map's equirectangular grid (weather/weather_map.h: texel centres, longitude
// wrap, blend to the pole's value within half a row of a pole). Each texel holds the
// albedo times a weight and the weight, 1 where a tile has set it and 0 elsewhere, so
// bilinear filtering gives, at any point,
//   albedo = R + (1 - G) * a_global
// (R, G the filtered channels, a_global the weather's global albedo, rgb): the tiles'
// albedo where they reach, the global value elsewhere, blended over one texel at a tile's
// edge. Snow cover and coastlines change over days, not minutes, so the map is not part of
// the weather timeline: a tile's albedo applies from the next frame, whatever its
// valid-at time.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "weather/map_tile.h"
#include "weather/weather_map.h"

namespace cloudsvc::weather {

class GroundAlbedoMap {
 public:
  // An empty map (the global albedo everywhere) of the given grid, texels.
  GroundAlbedoMap(int width, int height);

  // Writes the tile's albedo channel (tile.channels must include kGroundAlbedoTileChannel,
  // and the tile have no problem()) at every texel whose centre lies inside the tile.
  void apply(const MapTile& tile);
  // Back to the global albedo everywhere.
  void clear();

  // True once a tile has set any texel.
  bool any() const { return any_; }
  // Incremented by every apply() and clear(): the GPU copy is current while it matches.
  std::uint64_t version() const { return version_; }
  // R = albedo x weight, G = weight, B = A = 0 (the GPU uploads it as it is).
  const WeatherMap& texels() const { return texels_; }

  // The albedo at a geodetic position (rgb), given the global one.
  glm::dvec3 at(double lat_deg, double lon_deg, const glm::dvec3& global) const;

 private:
  WeatherMap texels_;
  bool any_ = false;
  std::uint64_t version_ = 0;
};

}  // namespace cloudsvc::weather
