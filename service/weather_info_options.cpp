// Command line of `cloudsvc weather-info` (weather_info_options.h).
#include "service/weather_info_options.h"

#include <CLI/CLI.hpp>

#include "common/option_values.h"

namespace cloudsvc::cli {

struct WeatherInfoCommandLine::Args {
  CLI::App* command = nullptr;
  std::vector<std::string> files;
  std::string at;
};

WeatherInfoCommandLine::WeatherInfoCommandLine(CLI::App& app) : args_(std::make_unique<Args>()) {
  Args& a = *args_;
  a.command = app.add_subcommand("weather-info",
                                 "Print the cloud layers the renderer derives from weather files at one point and time");
  a.command->add_option("files", a.files,
                        "GRIB2 forecasts (.grib2, .grb2, .grib, .grb) or METAR reports (.metar, .txt), all of one "
                        "kind (docs/WEATHER.md)")
      ->required()
      ->type_name("FILE...");
  a.command->add_option("--at", a.at,
                        "Where and when: LAT,LON in degrees (latitude [-90, 90], longitude [-180, 360]) and optionally "
                        ",TIME in UTC ISO 8601; without TIME the first forecast step or report (METAR reports are dated "
                        "by TIME, else by the current date)")
      ->required()
      ->type_name("LAT,LON[,TIME]");
  a.command->footer(
      "Prints one JSON object to stdout: {\"layers\": [{\"type\", \"base_m\", \"top_m\", \"coverage\"}, ...], "
      "\"lat\", \"lon\", \"time\", \"steps\"}; altitudes in m above the ellipsoid, coverage 0-1 at that point.\n"
      "Example:\n  cloudsvc weather-info gfs.grib2 --at 47.45,8.56,2026-06-21T12:00:00Z\n"
      "Exit codes: 0 ok, 2 bad input (the file and the problem on stderr).");
}

WeatherInfoCommandLine::~WeatherInfoCommandLine() = default;

bool WeatherInfoCommandLine::parsed() const { return args_->command->parsed(); }

WeatherInfoOptions WeatherInfoCommandLine::validate() const {
  const Args& a = *args_;
  WeatherInfoOptions opt;
  opt.files = a.files;
  const PlaceAndTime at = parse_place_and_time("--at", a.at);
  opt.lat_deg = at.lat_deg;
  opt.lon_deg = at.lon_deg;
  opt.utc_s = at.utc_s;
  return opt;
}

}  // namespace cloudsvc::cli
