// Plausibility limits for pose values read from flight logs, shared by the readers.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cloudsvc::sim {

// Heights accepted from logs, metres above the ellipsoid: from below the deepest
// depression (Dead Sea shore -430 m MSL, geoid down to -106 m) to 200 km (far above any
// aircraft or balloon; anything higher is a corrupt value, not a flight).
inline constexpr double kMinAltitude_m = -2000.0;
inline constexpr double kMaxAltitude_m = 200000.0;

// Unix times (s) of 1900-01-01T00:00:00Z and 2200-01-01T00:00:00Z: the years a log's samples
// may have (those of the ISO 8601 parser and of the protocol's Pose.utc_unix_s).
inline constexpr double kMinUnixTime = -2208988800.0;
inline constexpr double kEndUnixTime = 7258118400.0;

// nullopt when v is finite and in [lo, hi]; otherwise the problem, e.g.
// "latitude 95.5 out of range [-90, 90]" or "latitude is not finite (nan)".
std::optional<std::string> range_problem(std::string_view name, double v, double lo, double hi);

// nullopt when v is finite; otherwise "<name> is not finite (<v>)".
std::optional<std::string> finite_problem(std::string_view name, double v);

}  // namespace cloudsvc::sim
