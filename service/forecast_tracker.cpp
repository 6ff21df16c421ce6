// Forecast weather following the poses (forecast_tracker.h).
#include "service/forecast_tracker.h"

#include <algorithm>
#include <cmath>

#include "renderer/cloud_renderer.h"
#include "weather/forecast_frame.h"
#include "weather/sphere_geometry.h"
#include "weather/weather_timeline.h"

namespace cloudsvc {

ForecastTracker::ForecastTracker(std::shared_ptr<const weather::ForecastWeather> forecast, int map_width, int map_height)
    : forecast_(std::move(forecast)), map_width_(map_width), map_height_(map_height), steps_(forecast_->valid_times()) {}

std::vector<std::pair<double, weather::WeatherMap>> ForecastTracker::keyframes_around(double utc_s) {
  const std::size_t n = steps_.size(), k = std::min(n, weather::WeatherTimeline::kMaxKeyframes);
  // the step at or before the time, with up to a third of the keyframes before it
  const std::size_t at = static_cast<std::size_t>(
      std::max<std::ptrdiff_t>(0, std::upper_bound(steps_.begin(), steps_.end(), utc_s) - steps_.begin() - 1));
  first_ = std::min(at - std::min(at, k / 3), n - k);
  count_ = k;
  std::vector<std::pair<double, weather::WeatherMap>> frames;
  for (std::size_t i = first_; i < first_ + count_; ++i)
    frames.emplace_back(steps_[i], weather::forecast_map(*forecast_, steps_[i], map_width_, map_height_));
  return frames;
}

void ForecastTracker::update(CloudRenderer& renderer, double lat_deg, double lon_deg, double utc_s) {
  const bool before = first_ > 0 && utc_s < steps_[first_];
  const bool after = first_ + count_ < steps_.size() && utc_s > steps_[first_ + count_ - 1];
  if (count_ == 0 || before || after || !renderer.has_forecast()) {
    std::vector<std::pair<double, weather::WeatherMap>> frames = keyframes_around(utc_s);
    renderer.set_forecast(weather::forecast_weather_at(*forecast_, lat_deg, lon_deg, utc_s), std::move(frames));
  } else if (weather::surface_distance_m(lat_deg, lon_deg, lat_, lon_) > 0.5 * weather::kForecastRegion_m ||
             std::abs(utc_s - utc_) > kLayerRefresh_s) {
    renderer.update_forecast_layers(weather::forecast_weather_at(*forecast_, lat_deg, lon_deg, utc_s));
  } else {
    return;
  }
  lat_ = lat_deg;
  lon_ = lon_deg;
  utc_ = utc_s;
}

}  // namespace cloudsvc
