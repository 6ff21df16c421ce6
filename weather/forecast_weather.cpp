// Loading forecast weather by file kind (forecast_weather.h).
#include "weather/forecast_weather.h"

#include "weather/gridded_weather.h"
#include "weather/station_weather.h"
#include "weather/weather_json.h"

namespace cloudsvc::weather {

bool is_forecast_path(const std::string& path) { return is_grib_path(path) || is_metar_path(path); }

std::unique_ptr<ForecastWeather> load_forecast_weather(const std::vector<std::string>& paths, double reference_utc_s) {
  if (paths.empty()) throw WeatherFileError("no weather files given");
  for (const std::string& p : paths) {
    if (!is_forecast_path(p))
      throw WeatherFileError(p + ": not a forecast file (expected .grib2, .grb2, .grib or .grb for GRIB2, "
                                 ".metar or .txt for METAR reports)");
    if (is_grib_path(p) != is_grib_path(paths.front()))
      throw WeatherFileError(p + ": GRIB2 and METAR files cannot be mixed (" + paths.front() + " is " +
                             (is_grib_path(paths.front()) ? "GRIB2" : "METAR") + ")");
  }
  if (is_grib_path(paths.front())) return std::make_unique<GriddedWeather>(GriddedWeather::load_grib(paths));
  auto stations = std::make_unique<StationWeather>(
      StationWeather::from_reports(load_metar_file(paths.front(), reference_utc_s), paths.front()));
  for (std::size_t i = 1; i < paths.size(); ++i)
    stations->merge(StationWeather::from_reports(load_metar_file(paths[i], reference_utc_s), paths[i]));
  return stations;
}

}  // namespace cloudsvc::weather
