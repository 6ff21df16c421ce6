// `cloudsvc weather-info FILE... --at LAT,LON[,ISO_TIME]`: the cloud layers the renderer
// derives from weather files at one point and time, printed as one JSON object, so that a
// user (and a test) can check how a forecast maps onto layers (docs/WEATHER.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace cloudsvc {

struct WeatherInfoOptions {
  std::vector<std::string> files;  // GRIB2 or METAR files (docs/WEATHER.md)
  double lat_deg = 0.0;            // --at LAT,LON[,TIME]
  double lon_deg = 0.0;
  std::optional<double> utc_s;     // absent: the first step or report; METAR dates: now
};

namespace cli {

// Registers the sub-command on `app`; validate() after parsing (FlagError on bad values).
class WeatherInfoCommandLine {
 public:
  struct Args;
  explicit WeatherInfoCommandLine(CLI::App& app);
  ~WeatherInfoCommandLine();
  WeatherInfoCommandLine(const WeatherInfoCommandLine&) = delete;
  WeatherInfoCommandLine& operator=(const WeatherInfoCommandLine&) = delete;

  bool parsed() const;
  WeatherInfoOptions validate() const;

 private:
  std::unique_ptr<Args> args_;
};

}  // namespace cli

// Runs the sub-command: prints {"layers": [...], ...} to stdout and returns 0, or prints one
// line naming the file and the problem to stderr and returns 2.
int run_weather_info(const WeatherInfoOptions& opt);

}  // namespace cloudsvc
