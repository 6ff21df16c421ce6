// Flag value parsing of sim_client (cli_values.h).
#include "sim_client/cli_values.h"

#include <cmath>
#include <cstdio>

#include "geodesy/utc_time.h"
#include "protocol/messages.h"
#include "sim_client/text_input.h"

namespace cloudsvc::sim {

namespace {

// "" for empty text so that the message still shows a value.
std::string shown(std::string_view text) { return text.empty() ? std::string("\"\"") : std::string(text); }

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// Splits at every `sep` (empty fields kept).
std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t k = s.find(sep, start);
    if (k == std::string_view::npos) {
      out.push_back(s.substr(start));
      return out;
    }
    out.push_back(s.substr(start, k - start));
    start = k + 1;
  }
}

// A finite number without surrounding spaces; nullopt otherwise.
std::optional<double> strict_finite(std::string_view s) {
  if (s.empty() || s != trim(s)) return std::nullopt;
  if (s.size() > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) return std::nullopt;
  const std::optional<double> v = parse_number(s);
  if (!v || !std::isfinite(*v)) return std::nullopt;
  return v;
}

struct ChannelName {
  const char* name;
  std::uint8_t bit;
};
constexpr ChannelName kChannels[] = {
    {"coverage", protocol::tile_channel::kCoverage},
    {"development", protocol::tile_channel::kVerticalDevelopment},
    {"vertical-development", protocol::tile_channel::kVerticalDevelopment},
    {"density", protocol::tile_channel::kDensity},
    {"precipitation", protocol::tile_channel::kPrecipitation},
};

}  // namespace

void fail_flag(std::string_view flag, std::string_view value, std::string_view reason) {
  throw UsageError(std::string(flag) + " " + shown(value) + ": " + std::string(reason));
}

std::string number_text(double v) { return format_number(v); }

std::string range_text(const NumberRange& r) {
  std::string s = r.min_exclusive ? "(" : "[";
  s += number_text(r.min) + ", " + number_text(r.max) + "]";
  if (*r.unit) s += std::string(" (") + r.unit + ")";
  return s;
}

double parse_flag_number(std::string_view flag, const std::string& text, const NumberRange& r) {
  const std::optional<double> v = strict_finite(text);
  if (!v) fail_flag(flag, text, "expected a finite number in " + range_text(r));
  const bool below = r.min_exclusive ? *v <= r.min : *v < r.min;
  if (below || *v > r.max) fail_flag(flag, text, "out of range " + range_text(r));
  return *v;
}

long long parse_flag_integer(std::string_view flag, const std::string& text, long long min, long long max,
                             std::string_view unit) {
  std::string range = "[";
  range += std::to_string(min);
  range += ", ";
  range += std::to_string(max);
  range += "] (";
  range += unit;
  range += ')';
  if (!all_digits(text)) fail_flag(flag, text, "expected a whole number in " + range);
  // More digits than any limit here: out of range rather than an overflow.
  const long long v = text.size() > 15 ? max + 1 : std::stoll(text);
  if (v < min || v > max) fail_flag(flag, text, "out of range " + range);
  return v;
}

double parse_flag_duration(std::string_view flag, const std::string& text, double max_s) {
  double unit_s = 1.0;
  std::string number = text;
  if (!number.empty()) {
    const char last = number.back();
    if (last == 's' || last == 'm' || last == 'h') {
      unit_s = last == 'h' ? 3600.0 : last == 'm' ? 60.0 : 1.0;
      number.pop_back();
    }
  }
  const std::string expected = "expected seconds (90 or 90s), minutes (10m) or hours (1.5h), in (0, " +
                               number_text(max_s) + "] s";
  const std::optional<double> v = strict_finite(number);
  if (!v) fail_flag(flag, text, expected);
  const double seconds = *v * unit_s;
  if (!(seconds > 0.0) || seconds > max_s) fail_flag(flag, text, "out of range: " + expected);
  return seconds;
}

std::pair<std::uint32_t, std::uint32_t> parse_flag_size(std::string_view flag, const std::string& text,
                                                        std::uint32_t max_side) {
  const std::string expected = "expected WxH in pixels, each side in [1, " + std::to_string(max_side) + "], e.g. 640x360";
  std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) fail_flag(flag, text, expected);
  const std::string w = text.substr(0, x), h = text.substr(x + 1);
  if (!all_digits(w) || !all_digits(h)) fail_flag(flag, text, expected);
  const unsigned long long wv = w.size() > 9 ? ~0ull : std::stoull(w);
  const unsigned long long hv = h.size() > 9 ? ~0ull : std::stoull(h);
  if (wv < 1 || wv > max_side)
    fail_flag(flag, text, "width " + w + " out of range [1, " + std::to_string(max_side) + "] (pixels)");
  if (hv < 1 || hv > max_side)
    fail_flag(flag, text, "height " + h + " out of range [1, " + std::to_string(max_side) + "] (pixels)");
  return {static_cast<std::uint32_t>(wv), static_cast<std::uint32_t>(hv)};
}

double parse_flag_time(std::string_view flag, const std::string& text) {
  const std::optional<double> t = geo::parse_utc_iso8601(text);
  if (!t)
    fail_flag(flag, text,
              "expected a UTC ISO 8601 time YYYY-MM-DDTHH:MM[:SS]Z or with a ±hh:mm offset (years "
              "1900..2199), e.g. 2026-06-21T12:00:00Z");
  return *t;
}

GeoBounds parse_flag_bounds(std::string_view flag, const std::string& text) {
  const auto parts = split(text, ',');
  const char* expected = "expected lat_min,lon_min,lat_max,lon_max in degrees, e.g. 40,0,50,20";
  if (parts.size() != 4) fail_flag(flag, text, expected);
  double v[4];
  for (int i = 0; i < 4; ++i) {
    const std::optional<double> x = strict_finite(parts[static_cast<std::size_t>(i)]);
    if (!x) fail_flag(flag, text, expected);
    v[i] = *x;
  }
  GeoBounds b{v[0], v[1], v[2], v[3]};
  if (b.lat_min_deg < -90.0 || b.lat_max_deg > 90.0 || b.lat_min_deg >= b.lat_max_deg)
    fail_flag(flag, text, "latitudes must satisfy -90 <= lat_min < lat_max <= 90 (degrees)");
  if (b.lon_min_deg < -180.0 || b.lon_min_deg >= 180.0)
    fail_flag(flag, text, "lon_min must be in [-180, 180) (degrees)");
  if (b.lon_max_deg <= b.lon_min_deg || b.lon_max_deg > b.lon_min_deg + 360.0)
    fail_flag(flag, text,
              "lon_max must be in (lon_min, lon_min + 360] (degrees; above 180 crosses the antimeridian)");
  return b;
}

std::vector<std::uint8_t> parse_flag_channels(std::string_view flag, const std::string& text) {
  std::vector<std::uint8_t> bits;
  for (std::string_view name : split(text, ',')) {
    std::optional<std::uint8_t> bit;
    for (const ChannelName& c : kChannels)
      if (iequals(trim(name), c.name)) bit = c.bit;
    if (!bit)
      fail_flag(flag, text,
                "unknown channel '" + std::string(name) +
                    "' (expected a comma-separated list of coverage, development, density, precipitation)");
    for (std::uint8_t b : bits)
      if (b == *bit) fail_flag(flag, text, "channel " + channel_name(*bit) + " listed twice");
    bits.push_back(*bit);
  }
  return bits;
}

std::string channel_name(std::uint8_t bit) {
  for (const ChannelName& c : kChannels)
    if (c.bit == bit) return c.name;
  return "channel bit " + std::to_string(bit);
}

}  // namespace cloudsvc::sim
