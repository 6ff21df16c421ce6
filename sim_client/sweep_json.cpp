// JSON sweep files: explicit poses or a grid (format in sweep_plan.h).
#include <cmath>
#include <nlohmann/json.hpp>

#include "sim_client/sweep_plan.h"
#include "sim_client/sweep_support.h"
#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

using nlohmann::json;
using sweep_detail::WeatherRegistry;

// Deepest nesting a sweep file may have: a sweep (top level, poses, pose, inline weather,
// layers, layer, wind) needs 7; error messages and inline weather are serialised with
// json::dump, which recurses once per level, so a file of 300,000 nested '[' overflowed the
// stack before this bound.
constexpr int kMaxNesting = 32;

// True when j nests deeper than `limit` levels; the recursion itself stops at the limit.
bool nests_deeper_than(const json& j, int limit) {
  if (!j.is_structured()) return false;
  if (limit == 0) return true;
  for (const auto& child : j)
    if (nests_deeper_than(child, limit - 1)) return true;
  return false;
}

class JsonSweepParser {
 public:
  JsonSweepParser(const std::string& source, const std::filesystem::path& base_dir)
      : source_(source), registry_(plan_.weathers, base_dir) {}

  SweepPlan run(std::string_view text) {
    json root;
    try {
      root = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
      std::string what = e.what();
      const auto bracket = what.find("] ");
      if (bracket != std::string::npos) what = what.substr(bracket + 2);
      throw UsageError(source_ + ": " + what);
    }
    if (nests_deeper_than(root, kMaxNesting))
      fail("(top level)", "nested more than " + std::to_string(kMaxNesting) + " levels deep");
    if (!root.is_object()) fail("(top level)", "expected an object with \"poses\" or \"grid\"");
    check_keys(root, {"poses", "grid", "time", "weather", "description"}, "");
    if (root.contains("poses") == root.contains("grid"))
      fail("(top level)", "expected exactly one of \"poses\" and \"grid\"");
    if (root.contains("time")) default_time_ = time_value(root["time"], "time");
    if (root.contains("weather")) default_weather_ = weather_value(root["weather"], "weather");
    if (root.contains("description") && !root["description"].is_string())
      fail("description", "expected a string");
    if (root.contains("poses")) read_poses(root["poses"]);
    else read_grid(root["grid"]);
    return std::move(plan_);
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw UsageError(source_ + ": " + field + ": " + problem);
  }

  void check_keys(const json& obj, std::initializer_list<const char*> allowed, const std::string& path) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || it.key() == a;
      if (!ok) {
        std::string list;
        for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail(path.empty() ? it.key() : path + "." + it.key(), "unknown key (expected " + list + ")");
      }
    }
  }

  double number(const json& j, const std::string& field) const {
    if (!j.is_number()) fail(field, "expected a number, got " + std::string(j.type_name()) + " " + j.dump());
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(field, "not a finite number");
    return v;
  }

  double time_value(const json& j, const std::string& field) const {
    if (j.is_number()) return number(j, field);
    if (j.is_string()) {
      const std::optional<double> t = sweep_detail::parse_time_text(j.get<std::string>());
      if (!t) fail(field, "malformed time \"" + j.get<std::string>() + "\": expected ISO 8601 UTC, e.g. 2026-06-21T12:00:00Z");
      return *t;
    }
    fail(field, "expected an ISO 8601 UTC string or seconds since the Unix epoch");
  }

  std::size_t weather_value(const json& j, const std::string& field) {
    if (j.is_string()) return registry_.named(j.get<std::string>(), source_ + ": " + field);
    if (j.is_object()) return registry_.inline_json(j.dump(), source_ + ": " + field);
    fail(field, "expected a preset name, a .json path or a weather object");
  }

  void add(SweepEntry e) {
    if (auto p = sweep_detail::entry_problem(e)) fail(e.origin + "." + p->substr(0, p->find(':')), p->substr(p->find(':') + 2));
    if (plan_.entries.size() >= kMaxSweepEntries)
      fail(e.origin, "more than " + std::to_string(kMaxSweepEntries) + " entries");
    plan_.entries.push_back(std::move(e));
  }

  void read_poses(const json& poses) {
    if (!poses.is_array() || poses.empty()) fail("poses", "expected a non-empty array of pose objects");
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const std::string at = "poses[" + std::to_string(i) + "]";
      const json& p = poses[i];
      if (!p.is_object()) fail(at, "expected an object");
      check_keys(p, {"lat", "lon", "alt", "heading", "pitch", "roll", "time", "weather"}, at);
      for (const char* required : {"lat", "lon", "alt"})
        if (!p.contains(required)) fail(at + "." + required, "missing (required)");
      SweepEntry e;
      e.origin = at;
      e.lat_deg = number(p["lat"], at + ".lat");
      e.lon_deg = number(p["lon"], at + ".lon");
      e.alt_m = number(p["alt"], at + ".alt");
      if (p.contains("heading")) e.heading_deg = number(p["heading"], at + ".heading");
      if (p.contains("pitch")) e.pitch_deg = number(p["pitch"], at + ".pitch");
      if (p.contains("roll")) e.roll_deg = number(p["roll"], at + ".roll");
      e.utc_unix_s = p.contains("time") ? time_value(p["time"], at + ".time") : default_time_;
      e.weather = p.contains("weather") ? std::optional(weather_value(p["weather"], at + ".weather")) : default_weather_;
      add(std::move(e));
    }
  }

  // A grid axis: a number, or [first, last, count].
  std::vector<double> axis(const json& grid, const char* name, bool required) const {
    const std::string field = std::string("grid.") + name;
    if (!grid.contains(name)) {
      if (required) fail(field, "missing (required)");
      return {0.0};
    }
    const json& a = grid[name];
    if (a.is_number()) return {number(a, field)};
    if (!a.is_array() || a.size() != 3) fail(field, "expected a number or [first, last, count]");
    const double first = number(a[0], field + "[0]"), last = number(a[1], field + "[1]");
    const json& n = a[2];
    if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > static_cast<long long>(kMaxSweepEntries))
      fail(field + "[2]", "count must be an integer in [1, " + std::to_string(kMaxSweepEntries) +
                              "] written without a fraction or exponent (3, not 3.0 or 3e0), got " + n.dump());
    const long long count = n.get<long long>();
    std::vector<double> v(static_cast<std::size_t>(count));
    for (long long k = 0; k < count; ++k)
      v[static_cast<std::size_t>(k)] =
          count == 1 ? first : (k == count - 1 ? last : first + (last - first) * static_cast<double>(k) / static_cast<double>(count - 1));
    return v;
  }

  void read_grid(const json& grid) {
    if (!grid.is_object()) fail("grid", "expected an object of axes");
    check_keys(grid, {"lat", "lon", "alt", "heading", "pitch", "roll"}, "grid");
    const auto lat = axis(grid, "lat", true), lon = axis(grid, "lon", true), alt = axis(grid, "alt", true);
    const auto heading = axis(grid, "heading", false), pitch = axis(grid, "pitch", false), roll = axis(grid, "roll", false);
    const double total = static_cast<double>(lat.size()) * lon.size() * alt.size() * heading.size() * pitch.size() * roll.size();
    if (total > static_cast<double>(kMaxSweepEntries))
      fail("grid", "has " + format_number(total) + " combinations, at most " + std::to_string(kMaxSweepEntries));
    std::size_t k = 0;
    for (double la : lat)
      for (double lo : lon)
        for (double al : alt)
          for (double h : heading)
            for (double pi : pitch)
              for (double r : roll) {
                SweepEntry e;
                e.origin = "grid[" + std::to_string(k++) + "]";
                e.lat_deg = la;
                e.lon_deg = lo;
                e.alt_m = al;
                e.heading_deg = h;
                e.pitch_deg = pi;
                e.roll_deg = r;
                e.utc_unix_s = default_time_;
                e.weather = default_weather_;
                add(std::move(e));
              }
  }

  const std::string& source_;
  SweepPlan plan_;
  WeatherRegistry registry_;
  double default_time_ = kDefaultSweepTime_s;
  std::optional<std::size_t> default_weather_;
};

}  // namespace

SweepPlan parse_sweep_json(std::string_view text, const std::string& source, const std::filesystem::path& base_dir) {
  return JsonSweepParser(source, base_dir).run(text);
}

}  // namespace cloudsvc::sim
