// What the renderer draws from forecast weather (GRIB2 forecasts, METAR reports:
// forecast_weather.h) around a position at a time.
//
// The layers (cloud types, bases and tops) are those of the region around the position:
// each band averaged over points within kForecastRegion_m of it (cover as the mean over the
// points, base and top weighted by cover), then turned into layer slots and layers as at a
// point (cloud_column.h). Each layer reads its local coverage from its slot's channel of the
// weather map's layer coverage (CloudLayer::coverage_channel), which holds the slots' cover
// at every texel: the cloud is where the forecast puts it, at the altitudes of the region.
// Moving more than kForecastRegion_m / 2 calls for new layers (the service does). The
// visibility (the haze, one for the whole view) is the source's at the position itself
// (ForecastWeather::visibility_at), not averaged over the region.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "weather/cloud_layer.h"
#include "weather/forecast_weather.h"
#include "weather/weather_map.h"

namespace cloudsvc::weather {

inline constexpr double kForecastRegion_m = 150000.0;

// The regional column around a position (degrees) at a time (UTC seconds).
CloudColumn regional_column(const ForecastWeather& w, double lat_deg, double lon_deg, double utc_s);

// The weather of the region: its layers (each with its coverage channel) and the visibility
// at the position, named after the source; validate() accepts it.
Weather forecast_weather_at(const ForecastWeather& w, double lat_deg, double lon_deg, double utc_s);

// The forecast steps to hold as keyframes around a time: [first, first + count) of `steps`
// (valid times, ascending), count = min(steps.size(), max_count), starting up to a third of
// them before the step at or before utc_s (the first step when utc_s precedes all).
std::pair<std::size_t, std::size_t> keyframe_steps_around(const std::vector<double>& steps, double utc_s,
                                                          std::size_t max_count);

// A global map of width x height texels at a time: R, G, B neutral (0.5) and A 0, and every
// texel's slot covers (slot_covers) as its layer coverage. Rows in parallel on all cores.
WeatherMap forecast_map(const ForecastWeather& w, double utc_s, int width, int height);

}  // namespace cloudsvc::weather
