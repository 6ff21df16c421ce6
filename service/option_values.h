// Value parsers and checks shared by the sub-commands of `cloudsvc` (render_options.cpp,
// serve_options.cpp). CLI11 only collects each flag's text; these functions turn it into
// values or throw FlagError, whose what() is the one line printed after the command
// ("<flag> <value>: <what is wrong or expected, with range and unit>"). Internal to the
// command line; nothing here renders or creates files.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "service/serve_options.h"
#include "weather/cloud_layer.h"

namespace CLI {
class App;
}

namespace cloudsvc::cli {

constexpr const char* kProgram = "cloudsvc";
constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr int kMinImageSide = 1;     // px
constexpr int kMaxImageSide = 8192;  // px, per side

// ---- errors ------------------------------------------------------------------------------

// A flag whose value failed validation. what() is "<flag> <value>: <reason>".
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

// ---- numbers -------------------------------------------------------------------------------

// Interval of a numeric flag and its unit, for checks, messages and help.
struct Range {
  double min = 0.0;
  double max = 0.0;
  bool min_exclusive = false;  // (min, max] instead of [min, max]
  const char* unit = "";       // e.g. "degrees"
};

inline const Range kFieldOfView{0.0, 170.0, true, "degrees"};  // horizontal

// Shortest decimal text of a value for messages and help ("90", "47.45", "100000").
std::string format_number(double value);

// "[-90, 90] (degrees)" or "(0, 170] (degrees)".
std::string range_text(const Range& r);

// Parses the whole text as a finite decimal number ("95", "-0.5", "+1e3"). Rejects
// empty text, trailing characters, hexadecimal, "nan", "inf" and overflow.
std::optional<double> parse_finite_number(std::string_view text);

// Value of a numeric flag within `r`, or FlagError naming it.
double parse_number(std::string_view flag, const std::string& text, const Range& r);

// Parses text made only of decimal digits (no sign). Values too large for int become
// INT_MAX so that the caller's range check reports them.
std::optional<int> parse_digits(std::string_view text);

// Integer flag in [min, max] counted in `unit` (e.g. "clients"), or FlagError.
int parse_integer(std::string_view flag, const std::string& text, int min, int max,
                  std::string_view unit);

// A count of frames in [0, INT_MAX - 1]; `zero_means` explains 0 in the message
// (e.g. "0 = until the window is closed").
int parse_frame_count(std::string_view flag, const std::string& text,
                      std::string_view zero_means);

// WxH (or WXH): width and height in pixels, each in [1, 8192].
std::pair<int, int> parse_image_size(std::string_view flag, const std::string& text);

// ---- time and weather ----------------------------------------------------------------------

// UTC ISO 8601 -> seconds since the Unix epoch, or FlagError.
double parse_time(std::string_view flag, const std::string& text);

// Case-insensitive ASCII test of a file name ending (".json", ".png").
bool ends_with_ci(std::string_view text, std::string_view suffix);

std::string join(const std::vector<std::string>& items, std::string_view separator);

// A preset name, or a path ending in .json (any case) read as a weather file and
// validated; FlagError names the problem.
weather::Weather resolve_weather(std::string_view flag, const std::string& arg);

// ---- paths ---------------------------------------------------------------------------------

// `dir` (where a file or sub-directory will be created) exists, is a directory and is
// writable; otherwise FlagError for `flag value`.
void require_writable_directory(std::string_view flag, const std::string& value,
                                const std::filesystem::path& dir);

// FILE.png or FILE.exr (any case) in an existing, writable directory. The file itself is
// not created.
void check_output_file(std::string_view flag, const std::string& path);

// An existing writable directory, or an absent one whose nearest existing ancestor is a
// writable directory (the command creates it later, not the parser).
void check_output_directory(std::string_view flag, const std::string& dir_text);

// ---- help text -----------------------------------------------------------------------------

// "<what>; range <range> (<unit>); default <value>" for the help of a numeric flag.
std::string numeric_help(std::string_view what, const Range& r, double default_value);

// "Image size in pixels, width x height, each in [1, 8192]; default WxH".
std::string size_help(int width, int height);

// "<what>: a preset name (...) or a path to a weather file ending in .json ...; default X".
std::string weather_help(const std::string& default_arg, std::string_view what = "Weather");

// ---- `cloudsvc serve` (serve_options.cpp) -------------------------------------------------

// Registers the `serve` sub-command and its flags on `app` and keeps the collected text.
// After app.parse(): parsed() tells whether serve was the command; validate() converts
// the text into ServeOptions or throws FlagError.
class ServeCommandLine {
 public:
  struct Args;  // raw text of each flag (serve_options.cpp)

  explicit ServeCommandLine(CLI::App& app);
  ~ServeCommandLine();
  ServeCommandLine(const ServeCommandLine&) = delete;
  ServeCommandLine& operator=(const ServeCommandLine&) = delete;

  bool parsed() const;
  ServeOptions validate() const;

 private:
  std::unique_ptr<Args> args_;
};

}  // namespace cloudsvc::cli
