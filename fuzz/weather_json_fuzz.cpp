// Fuzz target: weather files, weather::parse_weather_json() (weather/weather_json.h), on any
// text, as `cloudsvc render --weather file.json` and `sim_client weather --layers` read them.
// Invariants checked besides the sanitizers':
//  - only WeatherFileError is thrown, with a one-line message starting with the file name;
//  - a returned Weather passes weather::validate() with its layers sorted by base;
//  - to_json() round-trips: parsing its output gives the same Weather, and printing that
//    gives the same text (the header promises this for every valid Weather).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_check.h"
#include "weather/cloud_layer.h"
#include "weather/weather_json.h"

namespace {

using namespace cloudsvc;

const std::string kSource = "fuzz.json";

bool same_layer(const weather::CloudLayer& a, const weather::CloudLayer& b) {
  return a.type == b.type && a.base_m == b.base_m && a.top_m == b.top_m && a.coverage == b.coverage &&
         a.density_scale == b.density_scale && a.droplet_diameter_um == b.droplet_diameter_um &&
         a.wind.east_mps == b.wind.east_mps && a.wind.north_mps == b.wind.north_mps;
}

bool same_weather(const weather::Weather& a, const weather::Weather& b) {
  if (a.name != b.name || a.map_seed != b.map_seed || a.layers.size() != b.layers.size()) return false;
  for (std::size_t i = 0; i < a.layers.size(); ++i)
    if (!same_layer(a.layers[i], b.layers[i])) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  weather::Weather w;
  try {
    w = weather::parse_weather_json(text, kSource);
  } catch (const weather::WeatherFileError& e) {
    const std::string what = e.what();
    FUZZ_CHECK(what.find_first_of("\r\n") == std::string::npos, "a weather-file error is not one line");
    FUZZ_CHECK(what.rfind(kSource + ": ", 0) == 0, "a weather-file error does not start with the file name");
    return 0;
  }
  const std::string problem = weather::validate(w);
  if (!problem.empty()) std::fprintf(stderr, "validate: %s\n", problem.c_str());
  FUZZ_CHECK(problem.empty(), "parse_weather_json() returned a Weather that validate() refuses");
  for (std::size_t i = 1; i < w.layers.size(); ++i)
    FUZZ_CHECK(w.layers[i - 1].base_m <= w.layers[i].base_m, "layers not sorted by base_m");

  const std::string printed = weather::to_json(w);
  weather::Weather again;
  try {
    again = weather::parse_weather_json(printed, kSource);
  } catch (const weather::WeatherFileError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    FUZZ_CHECK(false, "to_json() of a valid Weather does not parse");
  }
  FUZZ_CHECK(same_weather(w, again), "parse_weather_json(to_json(w)) differs from w");
  FUZZ_CHECK(weather::to_json(again) == printed, "to_json() is not stable over a round trip");
  return 0;
}
