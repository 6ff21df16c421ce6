// `cloudsvc weather-info` (weather_info_options.h).
#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/option_values.h"
#include "geodesy/utc_time.h"
#include "service/weather_info_options.h"
#include "weather/forecast_weather.h"
#include "weather/weather_json.h"

namespace cloudsvc {

int run_weather_info(const WeatherInfoOptions& opt) {
  try {
    // METAR reports carry only a day of the month: the asked time dates them, else now.
    const double now_s = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    const std::unique_ptr<weather::ForecastWeather> w = weather::load_forecast_weather(opt.files, opt.utc_s.value_or(now_s));
    const std::vector<double> times = w->valid_times();
    const double t = opt.utc_s.value_or(times.front());
    nlohmann::ordered_json out;
    out["lat"] = opt.lat_deg;
    out["lon"] = opt.lon_deg;
    out["time"] = geo::format_utc_iso8601(t);
    out["layers"] = nlohmann::ordered_json::array();
    for (const weather::CloudLayer& L : w->layers_at(opt.lat_deg, opt.lon_deg, t)) {
      nlohmann::ordered_json j;
      j["type"] = std::string(weather::cloud_type_name(L.type));
      j["base_m"] = L.base_m;
      j["top_m"] = L.top_m;
      j["coverage"] = L.coverage;
      out["layers"].push_back(j);
    }
    out["steps"] = nlohmann::ordered_json::array();
    for (double s : times) out["steps"].push_back(geo::format_utc_iso8601(s));
    std::cout << out.dump(2) << '\n';
    return 0;
  } catch (const weather::WeatherFileError& e) {
    std::cerr << "cloudsvc weather-info: " << cli::one_line(e.what()) << '\n';
    return 2;
  }
}

}  // namespace cloudsvc
