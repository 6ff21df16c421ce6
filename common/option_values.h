// Flag values of the `cloudsvc` and `sim_client` command lines (target
// cloudsvc_option_values). CLI11 only collects each flag's text; these functions turn it
// into checked values or throw FlagError, whose what() is the one line printed after the
// command: "<flag> <value>: <what is wrong or expected, with range and unit>". Nothing here
// renders, connects or creates files. Related checks: option_paths.h (files and
// directories), option_address.h (tcp://HOST:PORT, unix:PATH), option_weather.h (weather
// presets and files).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace cloudsvc::cli {

// Exit codes of both programs (docs/CLI.md, docs/SIM_CLIENT.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // runtime failure: no GL context, connection lost, write failed
inline constexpr int kExitBadInput = 2;  // a bad flag value or input file

inline constexpr int kMinImageSide = 1;     // px
inline constexpr int kMaxImageSide = 8192;  // px, per side

// ---- errors ------------------------------------------------------------------------------

// A flag whose value failed validation. what() is "<flag> <value>: <reason>", one line.
class FlagError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Replaces line breaks and other control characters so a message stays on one line.
std::string one_line(std::string_view text);

// Throws FlagError "<flag> <value>: <reason>" (an empty value shows as "").
[[noreturn]] void fail(std::string_view flag, std::string_view value, std::string_view reason);

// True if `flag` (an option of `cmd`) was given; FlagError if it was given more than once.
bool given(const CLI::App& cmd, const std::string& flag);

// Case-insensitive ASCII test of a file name ending (".json", ".png").
bool ends_with_ci(std::string_view text, std::string_view suffix);

std::string join(const std::vector<std::string>& items, std::string_view separator);

// ---- numbers -------------------------------------------------------------------------------

// Interval of a numeric flag and its unit, for checks, messages and help.
struct Range {
  double min = 0.0;
  double max = 0.0;
  bool min_exclusive = false;  // (min, max] instead of [min, max]
  const char* unit = "";       // e.g. "degrees"; "" = none
};

inline const Range kFieldOfView{0.0, 170.0, true, "degrees"};  // horizontal

// Shortest decimal text of a value for messages and help ("90", "47.45", "100000").
std::string format_number(double value);

// "[-90, 90] (degrees)" or "(0, 170] (degrees)"; without a unit "[0, 1]".
std::string range_text(const Range& r);

// Parses the whole text as a finite decimal number ("95", "-0.5", "+1e3"). Rejects
// empty text, spaces, trailing characters, hexadecimal, "nan", "inf" and overflow.
std::optional<double> parse_finite_number(std::string_view text);

// Value of a numeric flag within `r`, or FlagError naming it.
double parse_number(std::string_view flag, const std::string& text, const Range& r);

// Parses text made only of decimal digits (no sign). Values too large for int become
// INT_MAX so that the caller's range check reports them.
std::optional<int> parse_digits(std::string_view text);

// Whole number (decimal digits only) in [min, max] counted in `unit` (e.g. "clients"),
// or FlagError.
int parse_integer(std::string_view flag, const std::string& text, int min, int max, std::string_view unit);

// A count of frames in [0, INT_MAX - 1]; `zero_means` explains 0 in the message
// (e.g. "0 = until the window is closed").
int parse_frame_count(std::string_view flag, const std::string& text, std::string_view zero_means);

// WxH (or WXH): width and height in pixels, each in [1, max_side].
std::pair<int, int> parse_image_size(std::string_view flag, const std::string& text, int max_side = kMaxImageSide);

// A duration: a number of seconds, optionally with a unit suffix s, m (minutes) or h
// ("90", "90s", "10m", "1.5h"), in (0, max_s] seconds; returns seconds.
double parse_duration(std::string_view flag, const std::string& text, double max_s);

// ---- time ----------------------------------------------------------------------------------

// UTC ISO 8601 (YYYY-MM-DDTHH:MM[:SS[.fff]] then Z or +-hh:mm, years 1900..2199) ->
// seconds since the Unix epoch, or FlagError.
double parse_time(std::string_view flag, const std::string& text);

// A point and optionally a time, "LAT,LON[,TIME]": degrees (latitude [-90, 90], longitude
// [-180, 360]) and UTC ISO 8601 (parse_time). FlagError names the part that is wrong.
struct PlaceAndTime {
  double lat_deg = 0.0, lon_deg = 0.0;
  std::optional<double> utc_s;  // absent when TIME is not given
};
PlaceAndTime parse_place_and_time(std::string_view flag, const std::string& text);

// ---- help text -----------------------------------------------------------------------------

// "<what>; range <range> (<unit>); default <value>" for the help of a numeric flag.
std::string numeric_help(std::string_view what, const Range& r, double default_value);

// "Image size in pixels, width x height, each in [1, 8192]; default WxH".
std::string size_help(int width, int height);

}  // namespace cloudsvc::cli
