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
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = a.at.find(',', start);
    parts.push_back(a.at.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() < 2 || parts.size() > 3) fail("--at", a.at, "expected LAT,LON or LAT,LON,TIME");
  const auto number = [&](const std::string& text, double lo, double hi, const char* what) {
    const std::optional<double> v = parse_finite_number(text);
    if (!v || *v < lo || *v > hi)
      fail("--at", a.at, std::string(what) + " '" + text + "' is not a number in [" + format_number(lo) + ", " + format_number(hi) + "] (degrees)");
    return *v;
  };
  opt.lat_deg = number(parts[0], -90.0, 90.0, "latitude");
  opt.lon_deg = number(parts[1], -180.0, 360.0, "longitude");
  if (parts.size() == 3) opt.utc_s = parse_time("--at", parts[2]);
  return opt;
}

}  // namespace cloudsvc::cli
