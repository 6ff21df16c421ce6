// Flag values of the `sim_client` command line: CLI11 collects each flag's text, these
// functions turn it into checked values or throw UsageError, whose what() is the one line
// printed after the command name: "<flag> <value>: <what is wrong or expected, with unit>".
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cloudsvc::sim {

// Exit codes of sim_client (docs/SIM_CLIENT.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // connection lost, service error, file not writable
inline constexpr int kExitBadInput = 2;  // bad flag, unreadable or malformed input file

// Bad input: a flag value or an input file. what() is one line.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Failure after the input was accepted (service refused something, file write failed).
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail_flag(std::string_view flag, std::string_view value, std::string_view reason);

// Interval of a numeric flag and its unit, for checks and messages.
struct NumberRange {
  double min = 0.0;
  double max = 0.0;
  bool min_exclusive = false;  // (min, max] instead of [min, max]
  const char* unit = "";
};
// "[-90, 90] (degrees)" or "(0, 170] (degrees)".
std::string range_text(const NumberRange& r);

// A finite decimal number within r ("12", "-0.5", "1e3"); rejects nan, inf, "12abc", "".
double parse_flag_number(std::string_view flag, const std::string& text, const NumberRange& r);
// A whole number in [min, max] (decimal digits only).
long long parse_flag_integer(std::string_view flag, const std::string& text, long long min, long long max,
                             std::string_view unit);
// A duration: a number of seconds, optionally with a unit suffix s, m (minutes) or h
// ("90", "90s", "10m", "1.5h"), in (0, max_s] seconds; returns seconds.
double parse_flag_duration(std::string_view flag, const std::string& text, double max_s);
// "WxH" (or "WXH"), each side in [1, max_side] pixels.
std::pair<std::uint32_t, std::uint32_t> parse_flag_size(std::string_view flag, const std::string& text,
                                                        std::uint32_t max_side = 8192);
// ISO 8601 UTC (YYYY-MM-DDTHH:MM[:SS[.fff]] then Z or ±hh:mm) -> seconds since the epoch.
double parse_flag_time(std::string_view flag, const std::string& text);

// Geographic bounds of a weather map: "lat_min,lon_min,lat_max,lon_max", degrees.
struct GeoBounds {
  double lat_min_deg = 0.0, lon_min_deg = 0.0, lat_max_deg = 0.0, lon_max_deg = 0.0;
};
// lat in [-90, 90] with lat_min < lat_max; lon_min in [-180, 180), lon_max in
// (lon_min, lon_min + 360] (lon_max > 180 crosses the antimeridian, as in the protocol).
GeoBounds parse_flag_bounds(std::string_view flag, const std::string& text);

// Weather-map channel names in the order given ("coverage,density") -> protocol
// tile_channel bits, one per name. Names: coverage, development (or
// vertical-development), density, precipitation; each at most once.
std::vector<std::uint8_t> parse_flag_channels(std::string_view flag, const std::string& text);
// The name of one tile_channel bit ("coverage", ...).
std::string channel_name(std::uint8_t bit);

// Shortest decimal text of a value ("90", "47.45", "1e+06").
std::string number_text(double v);

}  // namespace cloudsvc::sim
