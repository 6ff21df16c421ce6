// Weather flag values (option_weather.h).
#include "common/option_weather.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <filesystem>
#include <optional>
#include <system_error>

#include "common/option_values.h"
#include "weather/presets.h"
#include "weather/weather_json.h"

namespace cloudsvc::cli {

namespace fs = std::filesystem;

namespace {

// A weather file's error message usually starts with the file name, which the flag
// line already shows: drop that prefix.
std::string without_path_prefix(std::string message, const std::string& path) {
  const std::string prefix = path + ": ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return message;
}

std::string preset_list() { return join(weather::preset_names(), ", "); }

}  // namespace

weather::Weather weather_preset(std::string_view flag, const std::string& name) {
  if (std::optional<weather::Weather> w = weather::preset(name)) return *w;
  fail(flag, name, "unknown weather preset (expected one of " + preset_list() + ")");
}

weather::Weather load_weather_file(std::string_view flag, const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) fail(flag, path, "weather file not found");
  if (!fs::is_regular_file(status)) fail(flag, path, "not a regular file");
  weather::Weather w;
  try {
    w = weather::load_weather_json(path);
  } catch (const weather::WeatherFileError& e) {
    fail(flag, path, without_path_prefix(e.what(), path));
  } catch (const std::exception& e) {
    fail(flag, path, std::string("cannot read weather file: ") + e.what());
  }
  const std::string problem = weather::validate(w);
  if (!problem.empty()) fail(flag, path, problem);
  return w;
}

std::shared_ptr<const weather::ForecastWeather> load_forecast(std::string_view flag,
                                                              const std::vector<std::string>& paths,
                                                              double reference_utc_s) {
  try {
    return weather::load_forecast_weather(paths, reference_utc_s);
  } catch (const weather::WeatherFileError& e) {
    // The message starts with the file it is about: show that one as the flag's value.
    for (const std::string& path : paths)
      if (std::string(e.what()).rfind(path + ": ", 0) == 0) fail(flag, path, without_path_prefix(e.what(), path));
    fail(flag, join(paths, " "), e.what());
  }
}

std::vector<std::string> weather_flag_values(const CLI::App& cmd, const std::vector<std::string>& values,
                                             const std::string& default_arg) {
  return cmd.get_option("--weather")->count() > 0 ? values : std::vector<std::string>{default_arg};
}

WeatherChoice resolve_weather_choice(std::string_view flag, const std::vector<std::string>& values,
                                     double reference_utc_s) {
  if (values.empty()) fail(flag, "", "expected a preset name or weather files");
  if (values.size() == 1 && !weather::is_forecast_path(values.front()))
    return {resolve_weather(flag, values.front()), nullptr};
  for (const std::string& v : values)
    if (!weather::is_forecast_path(v))
      fail(flag, join(values, " "),
           "'" + v + "' among several values: several are only GRIB2 or METAR files; a preset or a .json weather "
           "file comes alone");
  return {weather::Weather{}, load_forecast(flag, values, reference_utc_s)};
}

weather::Weather resolve_weather(std::string_view flag, const std::string& arg) {
  if (ends_with_ci(arg, ".json")) return load_weather_file(flag, arg);
  if (std::optional<weather::Weather> w = weather::preset(arg)) return *w;
  fail(flag, arg,
       "unknown weather preset (expected one of " + preset_list() +
           ", or a path to a .json weather file, a GRIB2 forecast or METAR reports)");
}

std::string weather_help(const std::string& default_arg, std::string_view what) {
  return std::string(what) + ": a preset name (" + preset_list() +
         "), a path to a weather file ending in .json, or a GRIB2 forecast (.grib2, .grb2, .grib, .grb) or METAR "
         "reports (.metar, .txt) (docs/WEATHER.md); default " + default_arg;
}

}  // namespace cloudsvc::cli
