// A forecast step as a weather-map raster (forecast_raster.h).
#include "sim_client/forecast_raster.h"

#include <algorithm>

#include "weather/forecast_frame.h"

namespace cloudsvc::sim {

MapRaster forecast_raster(const weather::ForecastWeather& w, double utc_s, int width, int height) {
  const weather::WeatherMap map = weather::forecast_map(w, utc_s, width, height);
  MapRaster r;
  r.width = map.width;
  r.height = map.height;
  r.channel_bits = {protocol::tile_channel::kCoverage, protocol::tile_channel::kVerticalDevelopment,
                    protocol::tile_channel::kDensity, protocol::tile_channel::kPrecipitation};
  r.layer_channels = 0x0f;
  r.values.resize(static_cast<std::size_t>(width) * height * r.value_count());
  float* out = r.values.data();
  for (int row = 0; row < height; ++row) {
    const std::size_t j = static_cast<std::size_t>(height - 1 - row);  // the map's rows start in the south
    for (int col = 0; col < width; ++col) {
      const std::size_t texel = (j * width + col) * 4;
      out = std::copy_n(&map.rgba[texel], 4, out);
      out = std::copy_n(&map.layer_coverage[texel], 4, out);
    }
  }
  return r;
}

}  // namespace cloudsvc::sim
