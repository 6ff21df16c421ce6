// A weather-map tile of one channel (coverage modulation m) with the same value everywhere,
// for tests that stream a forecast in (weather/weather_timeline.h). Header-only: used by
// weather_* tests (cloudsvc_weather only) and renderer tests alike.
#pragma once

#include <cstddef>

#include "weather/weather_timeline.h"

namespace cloudsvc::test {

inline weather::MapTile coverage_tile(double lat0, double lon0, double lat1, double lon1, float value,
                                      double valid_at = 0.0, int width = 4, int height = 4) {
  weather::MapTile t;
  t.lat_min_deg = lat0;
  t.lon_min_deg = lon0;
  t.lat_max_deg = lat1;
  t.lon_max_deg = lon1;
  t.width = width;
  t.height = height;
  t.channels = 1;  // coverage only
  t.valid_at_utc_s = valid_at;
  t.data.assign(static_cast<std::size_t>(width) * height, value);
  return t;
}

}  // namespace cloudsvc::test
