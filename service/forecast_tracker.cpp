// Forecast weather following the poses (forecast_tracker.h).
#include "service/forecast_tracker.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "renderer/cloud_renderer.h"
#include "weather/forecast_frame.h"
#include "weather/sphere_geometry.h"
#include "weather/weather_timeline.h"

namespace cloudsvc {

ForecastTracker::ForecastTracker(std::shared_ptr<const weather::ForecastWeather> forecast, int map_width,
                                 int map_height, double start_utc_s)
    : forecast_(std::move(forecast)), map_width_(map_width), map_height_(map_height), steps_(forecast_->valid_times()) {
  std::size_t count = 0;
  std::tie(prepared_first_, count) =
      weather::keyframe_steps_around(steps_, start_utc_s, weather::WeatherTimeline::kMaxKeyframes);
  prepared_ = build_keyframes(prepared_first_, count);
}

std::vector<std::pair<double, weather::WeatherMap>> ForecastTracker::build_keyframes(std::size_t first,
                                                                                      std::size_t count) const {
  std::vector<std::pair<double, weather::WeatherMap>> frames;
  for (std::size_t i = first; i < first + count; ++i)
    frames.emplace_back(steps_[i], weather::forecast_map(*forecast_, steps_[i], map_width_, map_height_));
  return frames;
}

void ForecastTracker::update(CloudRenderer& renderer, double lat_deg, double lon_deg, double utc_s) {
  const bool before = first_ > 0 && utc_s < steps_[first_];
  const bool after = first_ + count_ < steps_.size() && utc_s > steps_[first_ + count_ - 1];
  if (count_ == 0 || before || after || !renderer.has_forecast()) {
    std::tie(first_, count_) = weather::keyframe_steps_around(steps_, utc_s, weather::WeatherTimeline::kMaxKeyframes);
    // the keyframes made at start-up when they are the ones needed, else new ones
    std::vector<std::pair<double, weather::WeatherMap>> frames =
        !prepared_.empty() && prepared_first_ == first_ ? std::move(prepared_) : build_keyframes(first_, count_);
    prepared_.clear();
    renderer.update_forecast(weather::forecast_weather_at(*forecast_, lat_deg, lon_deg, utc_s), std::move(frames));
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
