// Value parsers and checks shared by the `cloudsvc` sub-commands (see option_values.h).
#include "service/option_values.h"

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
#include <system_error>

#include "geodesy/utc_time.h"
#include "weather/presets.h"
#include "weather/weather_json.h"

namespace cloudsvc::cli {

namespace fs = std::filesystem;

// ---- errors ------------------------------------------------------------------------------

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) out.push_back(static_cast<unsigned char>(c) < 0x20 ? ' ' : c);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

void fail(std::string_view flag, std::string_view value, std::string_view reason) {
  std::string message(flag);
  message += ' ';
  message += value.empty() ? std::string_view("\"\"") : value;
  message += ": ";
  message += reason;
  throw FlagError(one_line(message));
}

// CLI11 keeps every occurrence (TakeLast policy); a flag given more than once is rejected
// here so that the message shows all its values.
bool given(const CLI::App& cmd, const std::string& flag) {
  const CLI::Option* option = cmd.get_option(flag);
  if (option->count() > 1) {
    fail(flag, join(option->results(), " "), "given more than once (each flag at most once)");
  }
  return option->count() > 0;
}

// ---- numbers -------------------------------------------------------------------------------

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::string range_text(const Range& r) {
  return std::string(r.min_exclusive ? "(" : "[") + format_number(r.min) + ", " +
         format_number(r.max) + "] (" + r.unit + ")";
}

namespace {

bool in_range(double value, const Range& r) {
  const bool above_min = r.min_exclusive ? value > r.min : value >= r.min;
  return above_min && value <= r.max;
}

}  // namespace

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

double parse_number(std::string_view flag, const std::string& text, const Range& r) {
  const std::optional<double> value = parse_finite_number(text);
  if (!value) fail(flag, text, "expected a finite number in " + range_text(r));
  if (!in_range(*value, r)) fail(flag, text, "out of range " + range_text(r));
  return *value;
}

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

int parse_integer(std::string_view flag, const std::string& text, int min, int max,
                  std::string_view unit) {
  const std::string range =
      "[" + std::to_string(min) + ", " + std::to_string(max) + "] (" + std::string(unit) + ")";
  const std::optional<int> value = parse_digits(text);
  if (!value) fail(flag, text, "expected an integer in " + range);
  if (*value < min || *value > max) fail(flag, text, "out of range " + range);
  return *value;
}

int parse_frame_count(std::string_view flag, const std::string& text,
                      std::string_view zero_means) {
  const std::optional<int> frames = parse_digits(text);
  if (!frames || *frames == INT_MAX) {
    fail(flag, text,
         "expected an integer number of frames in [0, " + std::to_string(INT_MAX - 1) + "] (" +
             std::string(zero_means) + ")");
  }
  return *frames;
}

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

// ---- time and weather ----------------------------------------------------------------------

double parse_time(std::string_view flag, const std::string& text) {
  const std::optional<double> unix_time_s = geo::parse_utc_iso8601(text);
  if (!unix_time_s) {
    fail(flag, text,
         "expected a UTC ISO 8601 time YYYY-MM-DDTHH:MM[:SS]Z (years 1900..2199), "
         "e.g. 2026-06-21T12:00:00Z");
  }
  return *unix_time_s;
}

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

namespace {

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

}  // namespace

weather::Weather resolve_weather(std::string_view flag, const std::string& arg) {
  if (ends_with_ci(arg, ".json")) return load_weather_file(flag, arg);
  if (std::optional<weather::Weather> w = weather::preset(arg)) return *w;
  fail(flag, arg,
       "unknown weather preset (expected one of " + join(weather::preset_names(), ", ") +
           ", or a path to a .json weather file)");
}

// ---- paths ---------------------------------------------------------------------------------

namespace {

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

}  // namespace

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

// ---- help text -----------------------------------------------------------------------------

std::string numeric_help(std::string_view what, const Range& r, double default_value) {
  return std::string(what) + "; range " + range_text(r) + "; default " +
         format_number(default_value);
}

std::string size_help(int width, int height) {
  return "Image size in pixels, width x height, each in [" + std::to_string(kMinImageSide) +
         ", " + std::to_string(kMaxImageSide) + "]; default " + std::to_string(width) + "x" +
         std::to_string(height);
}

std::string weather_help(const std::string& default_arg, std::string_view what) {
  return std::string(what) + ": a preset name (" + join(weather::preset_names(), ", ") +
         ") or a path to a weather file ending in .json (docs/WEATHER.md); default " +
         default_arg;
}

}  // namespace cloudsvc::cli
