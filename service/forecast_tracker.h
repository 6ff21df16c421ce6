// Forecast weather in `cloudsvc serve --weather FILE.grib2|.metar|.txt`: keeps the
// renderer's forecast (CloudRenderer::set_forecast) up with the poses it draws.
//   - Keyframes: the layer-coverage maps (weather/forecast_frame.h) of up to
//     WeatherTimeline::kMaxKeyframes forecast steps around the pose's time, blended in time
//     by the renderer; rebuilt around the time when it leaves them and more steps exist.
//   - Layers: those of the region around the pose, anew when the pose has moved more than
//     half the region's radius (kForecastRegion_m / 2) or the time by kLayerRefresh_s since.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "weather/forecast_weather.h"
#include "weather/weather_map.h"

namespace cloudsvc {

class CloudRenderer;

class ForecastTracker {
 public:
  static constexpr double kLayerRefresh_s = 600.0;

  // Makes the keyframes around start_utc_s (the service's --time) at once, so that the first
  // pose near that time finds them made (a 0.25° step takes about 0.1 s a keyframe).
  ForecastTracker(std::shared_ptr<const weather::ForecastWeather> forecast, int map_width, int map_height,
                  double start_utc_s);

  // Brings the renderer's forecast to a pose at (lat, lon) degrees and UTC seconds.
  void update(CloudRenderer& renderer, double lat_deg, double lon_deg, double utc_s);

  // Forecast steps the keyframes hold: [first, first + count) of valid_times().
  std::pair<std::size_t, std::size_t> keyframe_steps() const { return {first_, count_}; }

 private:
  // The maps of steps [first, first + count).
  std::vector<std::pair<double, weather::WeatherMap>> build_keyframes(std::size_t first, std::size_t count) const;

  std::shared_ptr<const weather::ForecastWeather> forecast_;
  int map_width_, map_height_;
  std::vector<double> steps_;
  std::size_t first_ = 0, count_ = 0;  // steps in the renderer's keyframes (count 0: none yet)
  std::vector<std::pair<double, weather::WeatherMap>> prepared_;  // made at start-up, until used
  std::size_t prepared_first_ = 0;                                // their first step
  double lat_ = 0.0, lon_ = 0.0, utc_ = 0.0;  // where and when the layers were made
};

}  // namespace cloudsvc
