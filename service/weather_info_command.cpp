// `cloudsvc weather-info` (weather_info_options.h).
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/option_values.h"
#include "geodesy/utc_time.h"
#include "service/weather_info_options.h"
#include "weather/gridded_weather.h"
#include "weather/weather_json.h"

namespace cloudsvc {

int run_weather_info(const WeatherInfoOptions& opt) {
  std::vector<std::string> grib;
  for (const std::string& f : opt.files) {
    if (!weather::is_grib_path(f)) {
      std::cerr << "cloudsvc weather-info: " << cli::one_line(f + ": not a weather file this command reads "
                                                              "(expected .grib2, .grb2, .grib or .grb)")
                << '\n';
      return 2;
    }
    grib.push_back(f);
  }
  try {
    const weather::GriddedWeather w = weather::GriddedWeather::load_grib(grib);
    const std::vector<double> steps = w.valid_times();
    const double t = opt.utc_s.value_or(steps.front());
    nlohmann::ordered_json out;
    out["lat"] = opt.lat_deg;
    out["lon"] = opt.lon_deg;
    out["time"] = geo::format_utc_iso8601(t);
    out["layers"] = nlohmann::ordered_json::array();
    for (const weather::CloudLayer& L : w.layers_at(opt.lat_deg, opt.lon_deg, t)) {
      nlohmann::ordered_json j;
      j["type"] = std::string(weather::cloud_type_name(L.type));
      j["base_m"] = L.base_m;
      j["top_m"] = L.top_m;
      j["coverage"] = L.coverage;
      out["layers"].push_back(j);
    }
    out["steps"] = nlohmann::ordered_json::array();
    for (double s : steps) out["steps"].push_back(geo::format_utc_iso8601(s));
    std::cout << out.dump(2) << '\n';
    return 0;
  } catch (const weather::WeatherFileError& e) {
    std::cerr << "cloudsvc weather-info: " << cli::one_line(e.what()) << '\n';
    return 2;
  }
}

}  // namespace cloudsvc
