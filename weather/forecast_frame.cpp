// Forecast weather -> the renderer's layers and layer-coverage map (forecast_frame.h).
#include "weather/forecast_frame.h"

#include <algorithm>
#include <cmath>

#include "common/parallel_for.h"
#include "weather/sphere_geometry.h"

namespace cloudsvc::weather {

namespace {

constexpr int kRings = 3, kPointsPerRing = 8;

// The point at distance d (m) and bearing b (rad) from (lat, lon) on the sphere.
void offset_point(double lat, double lon, double d, double b, double& lat_out, double& lon_out) {
  const double a = d / kMeanEarthRadius_m, p = lat * kRadPerDeg;
  const double sp = std::sin(p) * std::cos(a) + std::cos(p) * std::sin(a) * std::cos(b);
  lat_out = std::asin(std::clamp(sp, -1.0, 1.0)) / kRadPerDeg;
  lon_out = lon + std::atan2(std::sin(b) * std::sin(a) * std::cos(p), std::cos(a) - std::sin(p) * sp) / kRadPerDeg;
}

}  // namespace

CloudColumn regional_column(const ForecastWeather& w, double lat_deg, double lon_deg, double utc_s) {
  ColumnAverage region;
  region.add(w.column_at(lat_deg, lon_deg, utc_s), 1.0);
  for (int r = 1; r <= kRings; ++r)
    for (int k = 0; k < kPointsPerRing; ++k) {
      double lat, lon;
      offset_point(lat_deg, lon_deg, kForecastRegion_m * r / kRings, 2.0 * M_PI * (k + 0.5 * (r % 2)) / kPointsPerRing, lat, lon);
      region.add(w.column_at(lat, lon, utc_s), 1.0);
    }
  return region.result();
}

Weather forecast_weather_at(const ForecastWeather& w, double lat_deg, double lon_deg, double utc_s) {
  Weather out;
  out.name = w.name();
  out.layers = layers_from_column(regional_column(w, lat_deg, lon_deg, utc_s));
  out.visibility_m = w.visibility_at(lat_deg, lon_deg, utc_s);  // at the position: the haze around the viewer
  return out;
}

std::pair<std::size_t, std::size_t> keyframe_steps_around(const std::vector<double>& steps, double utc_s,
                                                          std::size_t max_count) {
  const std::size_t n = steps.size(), k = std::min(n, max_count);
  const auto at = static_cast<std::size_t>(
      std::max<std::ptrdiff_t>(0, std::upper_bound(steps.begin(), steps.end(), utc_s) - steps.begin() - 1));
  return {std::min(at - std::min(at, k / 3), n - k), k};
}

WeatherMap forecast_map(const ForecastWeather& w, double utc_s, int width, int height) {
  WeatherMap map;
  if (width <= 0 || height <= 0) return map;
  map.width = width;
  map.height = height;
  const std::size_t texels = static_cast<std::size_t>(width) * height;
  map.rgba.resize(texels * 4);
  for (std::size_t n = 0; n < texels; ++n) {
    map.rgba[4 * n] = map.rgba[4 * n + 1] = map.rgba[4 * n + 2] = 0.5f;
    map.rgba[4 * n + 3] = 0.0f;
  }
  map.layer_coverage.assign(texels * 4, 0.0f);
  parallel_for(height, kAllThreads, [&](int j) {
    const double lat = -90.0 + (j + 0.5) * 180.0 / height;
    for (int i = 0; i < width; ++i) {
      const double lon = -180.0 + (i + 0.5) * 360.0 / width;
      const std::array<float, kLayerSlots> c = slot_covers(w.column_at(lat, lon, utc_s));
      float* out = &map.layer_coverage[(static_cast<std::size_t>(j) * width + i) * 4];
      for (int k = 0; k < kLayerSlots; ++k) out[k] = c[k];
    }
  });
  return map;
}

}  // namespace cloudsvc::weather
