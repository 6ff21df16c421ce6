// Sweep files: a list of camera poses (with optional weather) rendered one by one by
// `sim_client sweep`. Formats (docs/SIM_CLIENT.md):
//
//   JSON, explicit poses:
//     {"time": "2026-06-21T12:00:00Z", "weather": "broken-cumulus",
//      "poses": [{"lat": 47.45, "lon": 8.56, "alt": 2500, "heading": 270, "pitch": 5,
//                 "roll": 0, "time": ..., "weather": ...}, ...]}
//   JSON, grid (every combination; lat outermost, roll innermost):
//     {"grid": {"lat": [47.0, 48.0, 3], "lon": [8.0, 9.0, 3], "alt": 2500,
//               "heading": [0, 270, 4], "pitch": 5},
//      "time": "2026-06-21T12:00:00Z", "weather": "scattered-cumulus"}
//     An axis is a number or [first, last, count] (count >= 1 evenly spaced values, first
//     and last included; count 1 gives first).
//   CSV: header naming time,lat,lon,alt,heading,pitch,roll (any order, case-insensitive)
//     and optionally weather; '#' comment lines and blank lines skipped.
//
// Units: degrees (WGS84 latitude/longitude, true heading, pitch nose up, roll right wing
// down), metres above the WGS84 ellipsoid, time ISO 8601 UTC text or seconds since the Unix
// epoch. Ranges are the protocol's Pose ranges. heading, pitch, roll default to 0, time to
// kDefaultSweepTime. A weather is a preset name, a path ending in .json (relative to the
// sweep file's directory) or, in JSON, an inline weather object (docs/WEATHER.md); without
// one the service's weather is left as it is.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "weather/cloud_layer.h"

namespace cloudsvc::sim {

inline constexpr std::size_t kMaxSweepEntries = 100000;
inline constexpr double kDefaultSweepTime_s = 1782043200.0;  // 2026-06-21T12:00:00Z

struct SweepWeather {
  std::string label;  // for the manifest: preset name, file name or the inline object's name
  weather::Weather weather;
};

struct SweepEntry {
  double lat_deg = 0.0, lon_deg = 0.0;  // WGS84, degrees
  double alt_m = 0.0;                   // metres above the ellipsoid
  double heading_deg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;
  double utc_unix_s = kDefaultSweepTime_s;
  std::optional<std::size_t> weather;  // index into SweepPlan::weathers; nullopt = unchanged
  std::string origin;                  // where it came from, for messages: "poses[3]", "line 7", "grid[12]"
};

struct SweepPlan {
  std::vector<SweepEntry> entries;
  std::vector<SweepWeather> weathers;  // distinct weathers the entries refer to
};

// Reads a sweep file, by extension (.json or .csv, case-insensitive). Throws UsageError
// (usage_errors.h) with one line naming the file and the field or line:
//   "sweep.json: poses[2].lat: 95 out of range [-90, 90] (degrees)"
//   "sweep.csv:4: unknown weather 'fog' (not a preset and not a .json file)"
SweepPlan load_sweep(const std::string& path);
SweepPlan parse_sweep_json(std::string_view text, const std::string& source, const std::filesystem::path& base_dir);
SweepPlan parse_sweep_csv(std::string_view text, const std::string& source, const std::filesystem::path& base_dir);

}  // namespace cloudsvc::sim
