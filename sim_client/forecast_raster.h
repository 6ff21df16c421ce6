// Forecast weather (GRIB2 forecasts, METAR reports: weather/forecast_weather.h) as the weather
// map `sim_client weather --grib|--metar` sends the service for one forecast step: the
// global map the service itself draws a forecast with (weather/forecast_frame.h,
// forecast_map): coverage, vertical development and density neutral (0.5), no
// precipitation, and at every texel the cover of the four layer slots, which the forecast's
// layers read through their coverage_channel.
#pragma once

#include "sim_client/map_tiles.h"
#include "weather/forecast_weather.h"

namespace cloudsvc::sim {

// The forecast at a time (UTC s) on a global width x height grid (equirectangular, bounds
// -90,-180,90,180), in image order (row 0 north): channels coverage, vertical development,
// density and precipitation, then layer-coverage slots 0..3.
MapRaster forecast_raster(const weather::ForecastWeather& w, double utc_s, int width, int height);

}  // namespace cloudsvc::sim
