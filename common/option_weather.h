// Flag values that name a weather: a preset (weather/presets.h) or a weather file
// (weather/weather_json.h, docs/WEATHER.md). FlagError (option_values.h) names the flag.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "weather/cloud_layer.h"
#include "weather/forecast_weather.h"

namespace CLI {
class App;
}

namespace cloudsvc::cli {

// The preset called `name`, or FlagError listing the presets.
weather::Weather weather_preset(std::string_view flag, const std::string& name);

// The weather file at `path`, read and validated; FlagError names the problem (not found,
// not a regular file, the file's first error).
weather::Weather load_weather_file(std::string_view flag, const std::string& path);

// Forecast weather from GRIB2 or METAR files, all of one kind (weather/forecast_weather.h;
// METAR reports dated by reference_utc_s), or FlagError naming the flag, the file and the
// problem.
std::shared_ptr<const weather::ForecastWeather> load_forecast(std::string_view flag,
                                                              const std::vector<std::string>& paths,
                                                              double reference_utc_s);

// A preset name, or a path ending in .json (any case) read as a weather file (forecast
// files are read by load_forecast).
weather::Weather resolve_weather(std::string_view flag, const std::string& arg);

// What a --weather flag's values name: one preset or .json weather file (resolve_weather),
// or one or more GRIB2 or METAR files (load_forecast). FlagError for anything else, e.g. a
// preset among several values.
struct WeatherChoice {
  weather::Weather weather;                                 // the preset or file; empty with a forecast
  std::shared_ptr<const weather::ForecastWeather> forecast;  // GRIB2 or METAR files, else null
};
// The values of a --weather option of `cmd` (a vector option: several values, also from
// repeating the flag), or {default_arg} when it was not given.
std::vector<std::string> weather_flag_values(const CLI::App& cmd, const std::vector<std::string>& values,
                                             const std::string& default_arg);

WeatherChoice resolve_weather_choice(std::string_view flag, const std::vector<std::string>& values,
                                     double reference_utc_s);

// "<what>: a preset name (...), a path to a weather file ending in .json, or a GRIB2
// forecast or METAR reports ...; default X".
std::string weather_help(const std::string& default_arg, std::string_view what = "Weather");

}  // namespace cloudsvc::cli
