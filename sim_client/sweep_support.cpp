// Weather specs and pose checks of sweep files (sweep_support.h).
#include "sim_client/sweep_support.h"

#include <cmath>

#include "geodesy/utc_time.h"
#include "protocol/limits.h"
#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"
#include "weather/presets.h"
#include "weather/weather_json.h"

namespace cloudsvc::sim::sweep_detail {

namespace {

bool ends_with_json(std::string_view s) {
  return s.size() >= 5 && iequals(s.substr(s.size() - 5), ".json");
}

std::string joined_presets() {
  std::string out;
  for (const std::string& n : weather::preset_names()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::optional<std::string> check(const char* field, double v, double lo, double hi, const char* unit) {
  if (v >= lo && v <= hi) return std::nullopt;
  return std::string(field) + ": " + format_number(v) + " out of range [" + format_number(lo) + ", " + format_number(hi) +
         "] (" + unit + ")";
}

}  // namespace

std::size_t WeatherRegistry::add(const std::string& key, SweepWeather w) {
  const auto it = index_.find(key);
  if (it != index_.end()) return it->second;
  out_.push_back(std::move(w));
  index_.emplace(key, out_.size() - 1);
  return out_.size() - 1;
}

std::size_t WeatherRegistry::named(const std::string& spec, const std::string& where) {
  if (const std::optional<weather::Weather> p = weather::preset(spec)) return add("preset:" + spec, {spec, *p});
  if (ends_with_json(spec)) {
    std::filesystem::path path(spec);
    if (path.is_relative()) path = base_dir_ / path;
    const std::string key = "file:" + path.lexically_normal().string();
    if (index_.count(key)) return index_[key];
    try {
      return add(key, {spec, weather::load_weather_json(path.string())});
    } catch (const weather::WeatherFileError& e) {
      throw UsageError(where + ": weather " + e.what());
    }
  }
  throw UsageError(where + ": unknown weather '" + spec + "' (a preset: " + joined_presets() +
                   "; or a path ending in .json)");
}

std::size_t WeatherRegistry::inline_json(const std::string& json_text, const std::string& where) {
  try {
    weather::Weather w = weather::parse_weather_json(json_text, where);
    const std::string label = w.name;
    return add("inline:" + json_text, {label, std::move(w)});
  } catch (const weather::WeatherFileError& e) {
    throw UsageError(e.what());
  }
}

std::optional<std::string> entry_problem(const SweepEntry& e) {
  using namespace protocol;
  if (auto p = check("lat", e.lat_deg, -90.0, 90.0, "degrees")) return p;
  if (auto p = check("lon", e.lon_deg, -180.0, 180.0, "degrees")) return p;
  if (auto p = check("alt", e.alt_m, kMinAltitude_m, kMaxAltitude_m, "metres above the WGS84 ellipsoid")) return p;
  if (auto p = check("heading", e.heading_deg, -kMaxAbsHeading_deg, kMaxAbsHeading_deg, "degrees")) return p;
  if (auto p = check("pitch", e.pitch_deg, -kMaxAbsPitch_deg, kMaxAbsPitch_deg, "degrees")) return p;
  if (auto p = check("roll", e.roll_deg, -kMaxAbsRoll_deg, kMaxAbsRoll_deg, "degrees")) return p;
  if (!(e.utc_unix_s >= kMinUtc_s && e.utc_unix_s < kMaxUtc_s))
    return "time: " + format_number(e.utc_unix_s) + " s outside the years 1900..2199";
  return std::nullopt;
}

std::optional<double> parse_time_text(std::string_view text) {
  text = trim(text);
  std::optional<double> t = parse_number(text);
  if (t && !std::isfinite(*t)) return std::nullopt;
  if (!t) t = geo::parse_utc_iso8601(text);
  return t;
}

}  // namespace cloudsvc::sim::sweep_detail
