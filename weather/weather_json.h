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

// Messages: "<file>: <field>: <problem>", e.g.
//   "w.json: layers[0].top_m: must be greater than base_m (1000), got 900";
// "<file>: cannot open: <strerror>" for unreadable files; syntax errors give line, column
// and byte. Unknown and duplicate keys, wrong JSON types and values failing validate() are
// errors. Layers are returned sorted by base_m; validate() passes on every result.
Weather load_weather_json(const std::string& path);
// The same from text; source_name stands for the file in messages and is the default name.
Weather parse_weather_json(const std::string& text, const std::string& source_name);
// Pretty-printed JSON with every field; parse_weather_json(to_json(w)) gives w back exactly
// (for a w that passes validate()).
std::string to_json(const Weather& w);

}  // namespace cloudsvc::weather
