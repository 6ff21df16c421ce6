// Command line of `cloudsvc` (CLI11). CLI11 only collects each flag's text and prints
// help; every value is then validated here (numbers, ranges, time, weather, output
// paths) so that a bad command fails before any rendering starts, with exactly one line
// on stderr naming the flag, the given value and what is allowed, and exit code 2.
#include "service/render_options.h"

#include <linux/magic.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "geodesy/geodetic.h"
#include "geodesy/utc_time.h"
#include "weather/presets.h"
#include "weather/weather_json.h"

namespace cloudsvc {
namespace {

namespace fs = std::filesystem;

constexpr const char* kProgram = "cloudsvc";
constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr int kMinImageSide = 1;     // px
constexpr int kMaxImageSide = 8192;  // px, per side

// ---------------------------------------------------------------------------------------
// Errors

// A flag whose value failed validation. what() is "<flag> <value>: <reason>".
class FlagError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Replaces line breaks and other control characters so a message stays on one line.
std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) out.push_back(static_cast<unsigned char>(c) < 0x20 ? ' ' : c);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

[[noreturn]] void fail(std::string_view flag, std::string_view value, std::string_view reason) {
  std::string message(flag);
  message += ' ';
  message += value.empty() ? std::string_view("\"\"") : value;
  message += ": ";
  message += reason;
  throw FlagError(one_line(message));
}

// ---------------------------------------------------------------------------------------
// Numbers

// Interval of a numeric flag and its unit, for checks, messages and help.
struct Range {
  double min = 0.0;
  double max = 0.0;
  bool min_exclusive = false;  // (min, max] instead of [min, max]
  const char* unit = "";       // e.g. "degrees"
};

const Range kLatitude{-90.0, 90.0, false, "degrees"};
const Range kLongitude{-180.0, 180.0, false, "degrees"};
const Range kAltitude{-500.0, 100000.0, false, "metres above the WGS84 ellipsoid"};
const Range kHeading{-360.0, 360.0, false, "degrees"};
const Range kPitch{-90.0, 90.0, false, "degrees"};
const Range kRoll{-180.0, 180.0, false, "degrees"};
const Range kFieldOfView{0.0, 170.0, true, "degrees"};
const Range kExposure{-20.0, 20.0, false, "EV"};

// Shortest decimal text of a value for messages and help ("90", "47.45", "100000").
std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

// "[-90, 90] (degrees)" or "(0, 170] (degrees)".
std::string range_text(const Range& r) {
  return std::string(r.min_exclusive ? "(" : "[") + format_number(r.min) + ", " +
         format_number(r.max) + "] (" + r.unit + ")";
}

bool in_range(double value, const Range& r) {
  const bool above_min = r.min_exclusive ? value > r.min : value >= r.min;
  return above_min && value <= r.max;
}

// Parses the whole text as a finite decimal number ("95", "-0.5", "+1e3"). Rejects
// empty text, trailing characters, hexadecimal, "nan", "inf" and overflow.
std::optional<double> parse_finite_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) return std::nullopt;
  }
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Value of a numeric flag, or FlagError naming it.
double parse_number(std::string_view flag, const std::string& text, const Range& r) {
  const std::optional<double> value = parse_finite_number(text);
  if (!value) fail(flag, text, "expected a finite number in " + range_text(r));
  if (!in_range(*value, r)) fail(flag, text, "out of range " + range_text(r));
  return *value;
}

// Parses text made only of decimal digits. Values too large for int become INT_MAX so
// that the caller's range check reports them.
std::optional<int> parse_digits(std::string_view text) {
  if (text.empty()) return std::nullopt;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
  }
  int value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) return INT_MAX;
  if (ec != std::errc()) return std::nullopt;
  return value;
}

// --window-frames N: a count of frames >= 0.
int parse_frame_count(std::string_view flag, const std::string& text) {
  const std::optional<int> frames = parse_digits(text);
  if (!frames || *frames == INT_MAX) {
    fail(flag, text, "expected an integer number of frames in [0, " + std::to_string(INT_MAX - 1) +
                         "] (0 = until the window is closed)");
  }
  return *frames;
}

// --size WxH: width and height in pixels, each in [1, 8192].
std::pair<int, int> parse_image_size(std::string_view flag, const std::string& text) {
  const std::string expected = "expected WxH with W and H integers in [" +
                               std::to_string(kMinImageSide) + ", " +
                               std::to_string(kMaxImageSide) + "] (pixels), e.g. 1280x720";
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) fail(flag, text, expected);
  const std::optional<int> width = parse_digits(std::string_view(text).substr(0, x));
  const std::optional<int> height = parse_digits(std::string_view(text).substr(x + 1));
  if (!width || !height) fail(flag, text, expected);
  const std::string side_range =
      " out of range [" + std::to_string(kMinImageSide) + ", " + std::to_string(kMaxImageSide) +
      "] (pixels)";
  if (*width < kMinImageSide || *width > kMaxImageSide) {
    fail(flag, text, "width " + std::to_string(*width) + side_range);
  }
  if (*height < kMinImageSide || *height > kMaxImageSide) {
    fail(flag, text, "height " + std::to_string(*height) + side_range);
  }
  return {*width, *height};
}

// Wraps a heading in degrees into [0, 360).
double wrap_heading_deg(double heading_deg) {
  const double wrapped = std::fmod(heading_deg, 360.0);
  if (wrapped < 0.0) return wrapped + 360.0 < 360.0 ? wrapped + 360.0 : 0.0;
  return wrapped;
}

// ---------------------------------------------------------------------------------------
// Time and weather

// --time: UTC ISO 8601 -> seconds since the Unix epoch.
double parse_time(std::string_view flag, const std::string& text) {
  const std::optional<double> unix_time_s = geo::parse_utc_iso8601(text);
  if (!unix_time_s) {
    fail(flag, text,
         "expected a UTC ISO 8601 time YYYY-MM-DDTHH:MM[:SS]Z (years 1900..2199), "
         "e.g. 2026-06-21T12:00:00Z");
  }
  return *unix_time_s;
}

// Case-insensitive ASCII test of a file name ending (".json", ".png").
bool ends_with_ci(std::string_view text, std::string_view suffix) {
  if (text.size() < suffix.size()) return false;
  const std::string_view tail = text.substr(text.size() - suffix.size());
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    const auto a = static_cast<unsigned char>(tail[i]);
    const auto b = static_cast<unsigned char>(suffix[i]);
    if (std::tolower(a) != std::tolower(b)) return false;
  }
  return true;
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (const std::string& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

// A weather file's error message usually starts with the file name, which the flag
// line already shows: drop that prefix.
std::string without_path_prefix(std::string message, const std::string& path) {
  const std::string prefix = path + ": ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return message;
}

weather::Weather load_weather_file(std::string_view flag, const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) fail(flag, path, "weather file not found");
  if (!fs::is_regular_file(status)) fail(flag, path, "not a regular file");
  weather::Weather w;
  try {
    w = weather::load_weather_json(path);
  } catch (const weather::WeatherFileError& e) {
    fail(flag, path, without_path_prefix(e.what(), path));
  } catch (const std::exception& e) {
    fail(flag, path, std::string("cannot read weather file: ") + e.what());
  }
  const std::string problem = weather::validate(w);
  if (!problem.empty()) fail(flag, path, problem);
  return w;
}

// --weather: a preset name or a path ending in .json.
weather::Weather resolve_weather(std::string_view flag, const std::string& arg) {
  if (ends_with_ci(arg, ".json")) return load_weather_file(flag, arg);
  if (std::optional<weather::Weather> w = weather::preset(arg)) return *w;
  fail(flag, arg,
       "unknown weather preset (expected one of " + join(weather::preset_names(), ", ") +
           ", or a path to a .json weather file)");
}

// ---------------------------------------------------------------------------------------
// Output paths

// Pseudo file systems where root passes access(W_OK) but no regular file can be created.
bool is_pseudo_filesystem(const fs::path& dir) {
  struct statfs info {};
  if (statfs(dir.c_str(), &info) != 0) return false;
  return info.f_type == PROC_SUPER_MAGIC || info.f_type == SYSFS_MAGIC;
}

// True if files can be created in the existing directory `dir`.
bool is_writable_directory(const fs::path& dir) {
  return access(dir.c_str(), W_OK | X_OK) == 0 && !is_pseudo_filesystem(dir);
}

// `dir` (where a file or sub-directory will be created) exists, is a directory and is
// writable; otherwise FlagError for `flag value`.
void require_writable_directory(std::string_view flag, const std::string& value,
                                const fs::path& dir) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) fail(flag, value, "directory " + dir.string() + " does not exist");
  if (!fs::is_directory(status)) fail(flag, value, dir.string() + " is not a directory");
  if (!is_writable_directory(dir)) {
    fail(flag, value, "directory " + dir.string() + " is not writable");
  }
}

// --out: FILE.png or FILE.exr (any case) in an existing, writable directory. The file
// itself is not created here.
void check_output_file(std::string_view flag, const std::string& path) {
  const fs::path file(path);
  const std::string name = file.filename().string();
  const bool known_extension = ends_with_ci(name, ".png") || ends_with_ci(name, ".exr");
  if (!known_extension || name.size() <= 4) {
    fail(flag, path, "expected a file name ending in .png (8-bit sRGB) or .exr (linear half float)");
  }
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  require_writable_directory(flag, path, dir);
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (fs::is_directory(status)) fail(flag, path, "is a directory");
  if (fs::exists(status) && access(file.c_str(), W_OK) != 0) {
    fail(flag, path, "existing file is not writable");
  }
}

// Deepest existing directory on the way to `path` (which does not exist).
fs::path nearest_existing_ancestor(const fs::path& path) {
  std::error_code ec;
  fs::path current = fs::absolute(path, ec).lexically_normal();
  while (!fs::exists(current, ec) && current.has_parent_path() &&
         current.parent_path() != current) {
    current = current.parent_path();
  }
  return current;
}

// demo --out-dir: an existing writable directory, or an absent one whose nearest
// existing ancestor is a writable directory (the renderer creates it later).
void check_output_directory(std::string_view flag, const std::string& dir_text) {
  if (dir_text.empty()) fail(flag, dir_text, "expected a directory path");
  const fs::path dir(dir_text);
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) fail(flag, dir_text, "exists and is not a directory");
    if (!is_writable_directory(dir)) fail(flag, dir_text, "directory is not writable");
    return;
  }
  const fs::path ancestor = nearest_existing_ancestor(dir);
  if (!fs::is_directory(ancestor, ec)) {
    fail(flag, dir_text, ancestor.string() + " is not a directory");
  }
  if (!is_writable_directory(ancestor)) {
    fail(flag, dir_text, "parent directory " + ancestor.string() + " is not writable");
  }
}

// ---------------------------------------------------------------------------------------
// Flag definitions (CLI11 collects text; the checks above convert it)

// "<what>; <range> (<unit>); default <value>" for the help of a numeric flag.
std::string numeric_help(std::string_view what, const Range& r, double default_value) {
  return std::string(what) + "; range " + range_text(r) + "; default " +
         format_number(default_value);
}

std::string size_help(int width, int height) {
  return "Image size in pixels, width x height, each in [" + std::to_string(kMinImageSide) +
         ", " + std::to_string(kMaxImageSide) + "]; default " + std::to_string(width) + "x" +
         std::to_string(height);
}

// Raw text of each `render` flag, as collected by CLI11.
struct RenderArgs {
  CLI::App* command = nullptr;
  std::string lat, lon, alt, heading, pitch, roll, time, fov, size, weather, out, frames, exposure;
  bool window = false;
};

// Raw text of each `demo` flag.
struct DemoArgs {
  CLI::App* command = nullptr;
  std::string out_dir, size;
};

void add_position_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--lat", args.lat,
                 numeric_help("Camera geodetic latitude, north positive", kLatitude,
                              defaults.position.lat_deg))
      ->type_name("DEG");
  cmd.add_option("--lon", args.lon,
                 numeric_help("Camera longitude, east positive, normalised to [-180, 180)",
                              kLongitude, defaults.position.lon_deg))
      ->type_name("DEG");
  cmd.add_option("--alt", args.alt,
                 numeric_help("Camera height", kAltitude, defaults.position.alt_m))
      ->type_name("M");
}

void add_attitude_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--heading", args.heading,
                 numeric_help("True heading, clockwise from true north, wrapped to [0, 360)",
                              kHeading, defaults.attitude.heading_deg))
      ->type_name("DEG");
  cmd.add_option("--pitch", args.pitch,
                 numeric_help("Pitch, nose up positive", kPitch, defaults.attitude.pitch_deg))
      ->type_name("DEG");
  cmd.add_option("--roll", args.roll,
                 numeric_help("Roll, right wing down positive", kRoll, defaults.attitude.roll_deg))
      ->type_name("DEG");
}

void add_view_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--time", args.time,
                 "Date and time in UTC, ISO 8601 (YYYY-MM-DDTHH:MM[:SS[.fff]]Z or +hh:mm "
                 "offset), years 1900..2199; sets the sun position; default " +
                     defaults.time_text)
      ->type_name("UTC");
  cmd.add_option("--fov", args.fov,
                 numeric_help("Horizontal field of view", kFieldOfView, defaults.fov_deg))
      ->type_name("DEG");
  cmd.add_option("--size", args.size, size_help(defaults.width, defaults.height))
      ->type_name("WxH");
  cmd.add_option("--weather", args.weather,
                 "Weather: a preset name (" + join(weather::preset_names(), ", ") +
                     ") or a path to a weather file ending in .json (docs/WEATHER.md); "
                     "default " + defaults.weather_arg)
      ->type_name("PRESET|FILE.json");
}

void add_output_flags(CLI::App& cmd, RenderArgs& args, const RenderOptions& defaults) {
  cmd.add_option("--out", args.out,
                 "Output image: .png (8-bit sRGB, tone mapped) or .exr (linear half float), "
                 "extension case-insensitive; its directory must exist and be writable; "
                 "default " + defaults.out_path + " (none with --window)")
      ->type_name("FILE");
  cmd.add_flag("--window", args.window,
               "Show the view in an interactive window instead of writing a file "
               "(--out optional; needs a display)");
  cmd.add_option("--window-frames", args.frames,
                 "With --window: close after N frames (integer >= 0; 0 = run until the "
                 "window is closed); default " + std::to_string(defaults.window_frames))
      ->type_name("N");
  cmd.add_option("--exposure", args.exposure,
                 numeric_help("Exposure offset for PNG tone mapping, photographic stops",
                              kExposure, defaults.exposure_ev))
      ->type_name("EV");
}

void add_render_command(CLI::App& app, RenderArgs& args) {
  const RenderOptions defaults;
  args.command = app.add_subcommand(
      "render", "Render one view of the clouds to an image file (or an interactive window)");
  args.command->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  add_position_flags(*args.command, args, defaults);
  add_attitude_flags(*args.command, args, defaults);
  add_view_flags(*args.command, args, defaults);
  add_output_flags(*args.command, args, defaults);
  args.command->footer(
      "Example:\n  cloudsvc render --lat 46.55 --lon 7.98 --alt 3500 --heading 180 "
      "--time 2026-06-21T16:00:00Z --weather scattered-cumulus --size 1280x720 --out view.exr\n"
      "Exit codes: 0 ok, 1 runtime failure (e.g. no GL context), 2 bad input.");
}

void add_demo_command(CLI::App& app, DemoArgs& args) {
  const DemoOptions defaults;
  args.command =
      app.add_subcommand("demo", "Render the documented demo scene set into a directory");
  args.command->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  args.command
      ->add_option("--out-dir", args.out_dir,
                   "Directory for the images; created if absent (its nearest existing parent "
                   "must be a writable directory); default " + defaults.out_dir)
      ->type_name("DIR");
  args.command->add_option("--size", args.size, size_help(defaults.width, defaults.height))
      ->type_name("WxH");
  args.command->footer(
      "Example:\n  cloudsvc demo --out-dir out --size 1280x720\n"
      "Exit codes: 0 ok, 1 runtime failure (e.g. no GL context), 2 bad input.");
}

void configure_app(CLI::App& app, RenderArgs& render, DemoArgs& demo) {
  app.name(kProgram);
  app.description(
      "cloudsvc: volumetric cloud renderer for flight simulators.\n"
      "Angles are degrees, altitudes metres above the WGS84 ellipsoid, times UTC.");
  app.require_subcommand(0, 1);
  app.footer(
      "Run `cloudsvc render --help` or `cloudsvc demo --help` for the flags of a "
      "sub-command.\nExit codes: 0 ok, 1 runtime failure (e.g. no GL context), 2 bad input.");
  add_render_command(app, render);
  add_demo_command(app, demo);
}

// ---------------------------------------------------------------------------------------
// Validation of the collected text

// True if `flag` was given. CLI11 keeps every occurrence (TakeLast policy); a flag given
// more than once is rejected here so that the message shows all its values.
bool given(const CLI::App& cmd, const std::string& flag) {
  const CLI::Option* option = cmd.get_option(flag);
  if (option->count() > 1) {
    fail(flag, join(option->results(), " "), "given more than once (each flag at most once)");
  }
  return option->count() > 0;
}

void apply_geometry(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--lat")) opt.position.lat_deg = parse_number("--lat", a.lat, kLatitude);
  if (given(cmd, "--lon")) {
    opt.position.lon_deg = geo::wrap_longitude_deg(parse_number("--lon", a.lon, kLongitude));
  }
  if (given(cmd, "--alt")) opt.position.alt_m = parse_number("--alt", a.alt, kAltitude);
  if (given(cmd, "--heading")) {
    opt.attitude.heading_deg = wrap_heading_deg(parse_number("--heading", a.heading, kHeading));
  }
  if (given(cmd, "--pitch")) opt.attitude.pitch_deg = parse_number("--pitch", a.pitch, kPitch);
  if (given(cmd, "--roll")) opt.attitude.roll_deg = parse_number("--roll", a.roll, kRoll);
  if (given(cmd, "--fov")) opt.fov_deg = parse_number("--fov", a.fov, kFieldOfView);
}

void apply_image(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--size")) std::tie(opt.width, opt.height) = parse_image_size("--size", a.size);
  if (given(cmd, "--exposure")) opt.exposure_ev = parse_number("--exposure", a.exposure, kExposure);
  opt.window = a.window;
  if (given(cmd, "--window-frames")) {
    opt.window_frames = parse_frame_count("--window-frames", a.frames);
    if (!opt.window) fail("--window-frames", a.frames, "only valid together with --window");
  }
}

// --time, --weather and --out are resolved even when not given (their defaults are text).
void apply_scene_and_output(const RenderArgs& a, RenderOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--time")) opt.time_text = a.time;
  opt.unix_time_s = parse_time("--time", opt.time_text);
  if (given(cmd, "--weather")) opt.weather_arg = a.weather;
  opt.weather = resolve_weather("--weather", opt.weather_arg);
  if (given(cmd, "--out")) {
    opt.out_path = a.out;
  } else if (opt.window) {
    opt.out_path.clear();  // window only, no file
    return;
  }
  check_output_file("--out", opt.out_path);
}

RenderOptions validate_render(const RenderArgs& args) {
  RenderOptions opt;
  apply_geometry(args, opt);
  apply_image(args, opt);
  apply_scene_and_output(args, opt);
  return opt;
}

DemoOptions validate_demo(const DemoArgs& args) {
  DemoOptions opt;
  const CLI::App& cmd = *args.command;
  if (given(cmd, "--size")) std::tie(opt.width, opt.height) = parse_image_size("--size", args.size);
  if (given(cmd, "--out-dir")) opt.out_dir = args.out_dir;
  check_output_directory("--out-dir", opt.out_dir);
  return opt;
}

// ---------------------------------------------------------------------------------------
// Reporting

// "cloudsvc render" when argv[1] names a sub-command, else "cloudsvc": the prefix of
// error lines.
std::string command_prefix(int argc, const char* const* argv) {
  if (argc > 1 && argv[1] != nullptr) {
    const std::string_view first = argv[1];
    if (first == "render" || first == "demo") return std::string(kProgram) + " " + argv[1];
  }
  return kProgram;
}

// Arguments CLI11 could not match, from the program and its sub-commands; flags first.
std::vector<std::string> unmatched_arguments(const CLI::App& app) {
  std::vector<std::string> flags;
  std::vector<std::string> others;
  std::vector<std::string> all = app.remaining();
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    const std::vector<std::string> extra = sub->remaining();
    all.insert(all.end(), extra.begin(), extra.end());
  }
  for (std::string& arg : all) (arg.rfind("-", 0) == 0 ? flags : others).push_back(std::move(arg));
  flags.insert(flags.end(), others.begin(), others.end());
  return flags;
}

// "<argument>: unknown flag" (or sub-command, or unexpected argument).
std::string unmatched_argument_text(const CLI::App& app, const std::string& argument) {
  if (argument.rfind("-", 0) == 0) return argument + ": unknown flag";
  if (app.get_subcommands().empty()) {
    return argument + ": unknown sub-command (expected render or demo)";
  }
  return argument + ": unexpected argument (flags take the form --name VALUE)";
}

// One line for a CLI11 parse error. Unknown flags, sub-commands and missing values are
// phrased here; any other CLI11 message is passed on (it names the flag).
std::string parse_error_text(const CLI::ParseError& e, const CLI::App& app,
                             const std::string& prefix) {
  const std::string what = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::vector<std::string> unmatched = unmatched_arguments(app);
    if (!unmatched.empty()) return unmatched_argument_text(app, unmatched.front());
  }
  const std::size_t colon = what.find(':');
  const bool missing_value = dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr &&
                             colon != std::string::npos && what.ends_with(" missing");
  if (missing_value) {
    return what.substr(0, colon) + ": missing value (see `" + prefix + " --help`)";
  }
  return what;
}

ParsedCommand report_error(ParsedCommand result, const std::string& prefix,
                           const std::string& message) {
  result.exit_code = kExitBadInput;
  result.error = one_line(prefix + ": " + message);
  std::cerr << result.error << '\n' << std::flush;
  return result;
}

ParsedCommand report_help(ParsedCommand result, const CLI::App& app) {
  std::cout << app.help() << std::flush;
  result.exit_code = kExitOk;
  return result;
}

// No sub-command: the overview on stderr, then the error line.
ParsedCommand report_missing_command(ParsedCommand result, const CLI::App& app) {
  result.exit_code = kExitBadInput;
  result.error = std::string(kProgram) + ": missing sub-command (expected render or demo)";
  std::cerr << app.help() << result.error << '\n' << std::flush;
  return result;
}

}  // namespace

ParsedCommand parse_command_line(int argc, const char* const* argv) {
  ParsedCommand result;
  const std::string prefix = command_prefix(argc, argv);
  CLI::App app;
  RenderArgs render_args;
  DemoArgs demo_args;
  try {
    configure_app(app, render_args, demo_args);
    if (argc > 0) app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    return report_help(std::move(result), app);
  } catch (const CLI::CallForAllHelp&) {
    return report_help(std::move(result), app);
  } catch (const CLI::ParseError& e) {
    return report_error(std::move(result), prefix, parse_error_text(e, app, prefix));
  }
  try {
    if (render_args.command->parsed()) {
      result.kind = ParsedCommand::Kind::Render;
      result.render = validate_render(render_args);
    } else if (demo_args.command->parsed()) {
      result.kind = ParsedCommand::Kind::Demo;
      result.demo = validate_demo(demo_args);
    } else {
      return report_missing_command(std::move(result), app);
    }
  } catch (const FlagError& e) {
    return report_error(std::move(result), prefix, e.what());
  }
  return result;
}

}  // namespace cloudsvc
