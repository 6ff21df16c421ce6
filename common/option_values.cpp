// Flag value parsers of cloudsvc and sim_client (option_values.h).
#include "common/option_values.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "geodesy/utc_time.h"

namespace cloudsvc::cli {

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

// ---- numbers -------------------------------------------------------------------------------

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::string range_text(const Range& r) {
  std::string text = std::string(r.min_exclusive ? "(" : "[") + format_number(r.min) + ", " +
                     format_number(r.max) + "]";
  if (*r.unit) text += std::string(" (") + r.unit + ")";
  return text;
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
  if (!value) fail(flag, text, "expected a whole number in " + range);
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

std::pair<int, int> parse_image_size(std::string_view flag, const std::string& text, int max_side) {
  const std::string sides = "[" + std::to_string(kMinImageSide) + ", " + std::to_string(max_side) + "] (pixels)";
  const std::string expected = "expected WxH with W and H integers in " + sides + ", e.g. 1280x720";
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) fail(flag, text, expected);
  const std::string_view width_text = std::string_view(text).substr(0, x);
  const std::string_view height_text = std::string_view(text).substr(x + 1);
  const std::optional<int> width = parse_digits(width_text);
  const std::optional<int> height = parse_digits(height_text);
  if (!width || !height) fail(flag, text, expected);
  // The side as typed: a value too large for int shows as given, not as INT_MAX.
  if (*width < kMinImageSide || *width > max_side) {
    fail(flag, text, "width " + std::string(width_text) + " out of range " + sides);
  }
  if (*height < kMinImageSide || *height > max_side) {
    fail(flag, text, "height " + std::string(height_text) + " out of range " + sides);
  }
  return {*width, *height};
}

double parse_duration(std::string_view flag, const std::string& text, double max_s) {
  double unit_s = 1.0;
  std::string_view number = text;
  if (!number.empty()) {
    const char last = number.back();
    if (last == 's' || last == 'm' || last == 'h') {
      unit_s = last == 'h' ? 3600.0 : last == 'm' ? 60.0 : 1.0;
      number.remove_suffix(1);
    }
  }
  const std::string expected =
      "expected seconds (90 or 90s), minutes (10m) or hours (1.5h), in (0, " + format_number(max_s) + "] s";
  const std::optional<double> value = parse_finite_number(number);
  if (!value) fail(flag, text, expected);
  const double seconds = *value * unit_s;
  if (!(seconds > 0.0) || seconds > max_s) fail(flag, text, "out of range: " + expected);
  return seconds;
}

// ---- time ----------------------------------------------------------------------------------

double parse_time(std::string_view flag, const std::string& text) {
  const std::optional<double> unix_time_s = geo::parse_utc_iso8601(text);
  if (!unix_time_s) {
    fail(flag, text,
         "expected a UTC ISO 8601 time YYYY-MM-DDTHH:MM[:SS[.fff]] with Z or a +hh:mm or -hh:mm "
         "offset (years 1900..2199), e.g. 2026-06-21T12:00:00Z");
  }
  return *unix_time_s;
}

PlaceAndTime parse_place_and_time(std::string_view flag, const std::string& text) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() < 2 || parts.size() > 3) fail(flag, text, "expected LAT,LON or LAT,LON,TIME");
  const auto number = [&](const std::string& part, double lo, double hi, const char* what) {
    const std::optional<double> v = parse_finite_number(part);
    if (!v || *v < lo || *v > hi)
      fail(flag, text, std::string(what) + " '" + part + "' is not a number in [" + format_number(lo) + ", " +
                           format_number(hi) + "] (degrees)");
    return *v;
  };
  PlaceAndTime p;
  p.lat_deg = number(parts[0], -90.0, 90.0, "latitude");
  p.lon_deg = number(parts[1], -180.0, 360.0, "longitude");
  if (parts.size() == 3) p.utc_s = parse_time(flag, parts[2]);
  return p;
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

}  // namespace cloudsvc::cli
