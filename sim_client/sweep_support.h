// Internal to the sweep readers (sweep_json.cpp, sweep_csv.cpp): weather specs and pose
// range checks shared by both formats.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "sim_client/sweep_plan.h"

namespace cloudsvc::sim::sweep_detail {

// Collects the distinct weathers of a plan. Lookups throw UsageError(`where` + ": " + problem).
class WeatherRegistry {
 public:
  WeatherRegistry(std::vector<SweepWeather>& out, std::filesystem::path base_dir)
      : out_(out), base_dir_(std::move(base_dir)) {}
  // A preset name or a path ending in .json (relative to base_dir).
  std::size_t named(const std::string& spec, const std::string& where);
  // An inline weather object as JSON text (weather_json.h format).
  std::size_t inline_json(const std::string& json_text, const std::string& where);

 private:
  std::size_t add(const std::string& key, SweepWeather w);
  std::vector<SweepWeather>& out_;
  std::filesystem::path base_dir_;
  std::map<std::string, std::size_t> index_;  // key -> position in out_
};

// nullopt when every value of e is in the protocol's Pose range; otherwise
// "<field>: <value> out of range [lo, hi] (unit)" with field lat, lon, alt, heading,
// pitch, roll or time.
std::optional<std::string> entry_problem(const SweepEntry& e);

// Time text: ISO 8601 UTC, or seconds since the Unix epoch as a plain number.
std::optional<double> parse_time_text(std::string_view text);

}  // namespace cloudsvc::sim::sweep_detail
