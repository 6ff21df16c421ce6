#include "weather/ground_albedo_map.h"

#include <bit>

#include "weather/weather_timeline.h"

namespace cloudsvc::weather {

GroundAlbedoMap::GroundAlbedoMap(int width, int height) {
  texels_.width = width;
  texels_.height = height;
  clear();
}

void GroundAlbedoMap::clear() {
  texels_.rgba.assign(static_cast<std::size_t>(texels_.width) * texels_.height * 4, 0.0f);
  any_ = false;
  ++version_;
}

void GroundAlbedoMap::apply(const MapTile& tile) {
  if (!(tile.channels & kGroundAlbedoTileChannel)) return;
  // the albedo is the tile's highest channel bit: the last value of each texel
  const int slot = std::popcount(static_cast<unsigned>(tile.channels)) - 1;
  resample_tile(texels_, tile, {slot, kResampleOne, kResampleKeep, kResampleKeep});
  any_ = true;
  ++version_;
}

glm::dvec3 GroundAlbedoMap::at(double lat_deg, double lon_deg, const glm::dvec3& global) const {
  if (!any_) return global;
  float v[4];
  texels_.sample(lat_deg, lon_deg, v);
  return glm::dvec3(v[0]) + (1.0 - static_cast<double>(v[1])) * global;
}

}  // namespace cloudsvc::weather
