// Weather from a JSON file (format in docs/WEATHER.md).
#pragma once

#include <stdexcept>
#include <string>

#include "weather/cloud_layer.h"

namespace cloudsvc::weather {

// Thrown with a one-line message that names the file and the offending field.
struct WeatherFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Weather load_weather_json(const std::string& path);
Weather parse_weather_json(const std::string& text, const std::string& source_name);
std::string to_json(const Weather& w);

}  // namespace cloudsvc::weather
