#include "weather/map_tile.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <span>

namespace cloudsvc::weather {
namespace {

// Shortest text that reads back to v ("91", "1e+300", "nan", "-inf"); the protocol's
// messages print numbers the same way (protocol/validate.cpp).
std::string num(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// One message line: the prefix, the field, then the rest (appending avoids GCC 12's false
// warnings about "literal" + std::string chains).
template <class... Parts>
std::string line(std::string_view prefix, std::string_view field, const Parts&... parts) {
  std::string s(prefix);
  s.append(field);
  (s.append(std::string_view(parts)), ...);
  return s;
}

using Problem = std::string;  // empty: none

Problem not_finite(std::string_view pre, std::string_view field, double v) {
  return line(pre, field, " is ", num(v), " (must be finite)");
}

// v in [lo, hi).
Problem closed_open(std::string_view pre, std::string_view field, double v, double lo, double hi) {
  if (!std::isfinite(v)) return not_finite(pre, field, v);
  if (v < lo || v >= hi) return line(pre, field, " ", num(v), " out of range [", num(lo), ", ", num(hi), ")");
  return {};
}

// v in (lo, hi].
Problem open_closed(std::string_view pre, std::string_view field, double v, double lo, double hi) {
  if (!std::isfinite(v)) return not_finite(pre, field, v);
  if (v <= lo || v > hi) return line(pre, field, " ", num(v), " out of range (", num(lo), ", ", num(hi), "]");
  return {};
}

Problem texels(std::string_view pre, std::string_view field, std::int64_t v) {
  if (v < 1 || v > kMaxTileTexels) {
    return line(pre, field, " ", std::to_string(v), " out of range [1, ", std::to_string(kMaxTileTexels), "]");
  }
  return {};
}

std::string_view channel_name(int bit) {
  switch (bit) {
    case 0:
      return "coverage";
    case 1:
      return "vertical_development";  // the protocol's name of the map's cloud-type channel
    case 2:
      return "density";
    case 3:
      return "precipitation";
    default:
      return "ground_albedo";
  }
}

#define CHECK(expr)                                  \
  do {                                               \
    if (Problem p_ = (expr); !p_.empty()) return p_; \
  } while (false)

}  // namespace

MapTileHeader MapTile::header() const {
  return MapTileHeader{lat_min_deg, lon_min_deg, lat_max_deg, lon_max_deg, width, height, channels, valid_at_utc_s};
}

std::string MapTile::problem(std::string_view field_prefix) const {
  const MapTileHeader h = header();
  CHECK(tile_header_problem(h, field_prefix));
  return tile_data_problem(h, data, field_prefix);
}

std::string tile_header_problem(const MapTileHeader& t, std::string_view pre) {
  CHECK(closed_open(pre, "lat_min_deg", t.lat_min_deg, -90.0, 90.0));
  CHECK(open_closed(pre, "lat_max_deg", t.lat_max_deg, t.lat_min_deg, 90.0));
  CHECK(closed_open(pre, "lon_min_deg", t.lon_min_deg, -180.0, 180.0));
  CHECK(open_closed(pre, "lon_max_deg", t.lon_max_deg, t.lon_min_deg, t.lon_min_deg + 360.0));
  CHECK(texels(pre, "width", t.width));
  CHECK(texels(pre, "height", t.height));
  if (const unsigned unknown = t.channels & ~unsigned{kAllTileChannels}) {
    char hex[8];
    const auto r = std::to_chars(hex, hex + sizeof hex, unknown, 16);
    return line(pre, "channels", " has unknown bits 0x", std::string_view(hex, r.ptr - hex));
  }
  if (t.channels == 0) return line(pre, "channels", " is empty");
  if (!std::isfinite(t.valid_at_utc_s)) return not_finite(pre, "valid_at_utc_s", t.valid_at_utc_s);
  return {};
}

std::string tile_data_problem(const MapTileHeader& t, std::span<const float> data, std::string_view pre) {
  const int nc = std::popcount(t.channels);
  const auto columns = static_cast<std::size_t>(t.width);
  const std::size_t expected = columns * static_cast<std::size_t>(t.height) * nc;
  if (data.size() != expected) {
    return line(pre, "data", " has ", std::to_string(data.size()), " values, expected ", std::to_string(expected),
                " (width ", std::to_string(t.width), " x height ", std::to_string(t.height), " x ",
                std::to_string(nc), " channels)");
  }
  for (std::size_t i = 0; i < data.size(); ++i) {
    const float v = data[i];
    if (v >= 0.0f && v <= 1.0f) continue;  // false for NaN
    const std::size_t texel = i / nc;
    int k = static_cast<int>(i % nc);
    int bit = 0;  // the k-th set bit of channels
    for (;; ++bit) {
      if ((t.channels >> bit) & 1) {
        if (k == 0) break;
        --k;
      }
    }
    return line(pre, "data", "[", std::to_string(i), "] ", num(static_cast<double>(v)), " out of range [0, 1] (col ",
                std::to_string(texel % columns), ", row ", std::to_string(texel / columns), ", ", channel_name(bit),
                ")");
  }
  return {};
}

#undef CHECK

}  // namespace cloudsvc::weather
