// Weather given as cloud bands over the globe and in time, from forecasts (GRIB2,
// gridded_weather.h) or observations (METAR reports, station_weather.h): the bands at any
// point and time, and the renderer's layers there (cloud_column.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "weather/cloud_column.h"

namespace cloudsvc::weather {

class ForecastWeather {
 public:
  virtual ~ForecastWeather() = default;

  // The bands over a point (degrees) at a time (UTC seconds), blended between the times
  // around it; before the first and after the last, the nearest holds.
  virtual CloudColumn column_at(double lat_deg, double lon_deg, double utc_s) const = 0;
  // The visibility over a point at a time (Weather::visibility_m, m, within its range), or
  // nullopt where the source gives none: the model's own clear air. METAR reports give their
  // prevailing visibility (station_weather.h); GRIB2 forecasts none (not read).
  virtual std::optional<double> visibility_at(double lat_deg, double lon_deg, double utc_s) const {
    return std::nullopt;
  }
  // The times the source gives weather for, ascending (UTC seconds); never empty.
  virtual std::vector<double> valid_times() const = 0;
  // The files it was read from, for logs.
  virtual const std::string& name() const = 0;

  // The renderer's layers at a point and time (layers_from_column).
  std::vector<CloudLayer> layers_at(double lat_deg, double lon_deg, double utc_s) const {
    return layers_from_column(column_at(lat_deg, lon_deg, utc_s));
  }
};

// True when the path names a file load_forecast_weather reads: GRIB2 (.grib2, .grb2, .grib,
// .grb) or METAR (.metar, .txt); any case.
bool is_forecast_path(const std::string& path);

// Reads GRIB2 or METAR files (all of one kind). METAR reports carry only a day of the month:
// reference_utc_s dates them (metar.h). Throws WeatherFileError naming the file and the
// problem; mixing the two kinds is an error.
std::unique_ptr<ForecastWeather> load_forecast_weather(const std::vector<std::string>& paths, double reference_utc_s);

}  // namespace cloudsvc::weather
