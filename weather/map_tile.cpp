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

Problem known_bits(std::string_view pre, std::string_view field, std::uint8_t bits, std::uint8_t known) {
  if (const unsigned unknown = bits & ~unsigned{known}) {
    char hex[8];
    const auto r = std::to_chars(hex, hex + sizeof hex, unknown, 16);
    return line(pre, field, " has unknown bits 0x", std::string_view(hex, r.ptr - hex));
  }
  return {};
}

Problem texels(std::string_view pre, std::string_view field, std::int64_t v) {
  if (v < 1 || v > kMaxTileTexels) {
    return line(pre, field, " ", std::to_string(v), " out of range [1, ", std::to_string(kMaxTileTexels), "]");
  }
  return {};
}

std::string_view tile_channel_name(int bit) {
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

// The name of value k of a texel (0 <= k < tile_value_count): its channel, or its layer
// coverage slot after the channels.
std::string channel_name(const MapTileHeader& t, int k) {
  for (int bit = 0; bit < 8; ++bit)
    if (((t.channels >> bit) & 1) && k-- == 0) return std::string(tile_channel_name(bit));
  for (int slot = 0; slot < 4; ++slot)
    if (((t.layer_channels >> slot) & 1) && k-- == 0) return "layer coverage " + std::to_string(slot);
  return "?";
}

#define CHECK(expr)                                  \
  do {                                               \
    if (Problem p_ = (expr); !p_.empty()) return p_; \
  } while (false)

}  // namespace

MapTileHeader MapTile::header() const {
  return MapTileHeader{lat_min_deg, lon_min_deg, lat_max_deg, lon_max_deg, width, height, channels, valid_at_utc_s,
                       layer_channels};
}

int tile_value_count(std::uint8_t channels, std::uint8_t layer_channels) {
  return std::popcount(channels) + std::popcount(layer_channels);
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
  CHECK(known_bits(pre, "channels", t.channels, kAllTileChannels));
  CHECK(known_bits(pre, "layer_channels", t.layer_channels, kAllLayerCoverageSlots));
  if (t.channels == 0 && t.layer_channels == 0) return line(pre, "channels", " and layer_channels are empty");
  if (!std::isfinite(t.valid_at_utc_s)) return not_finite(pre, "valid_at_utc_s", t.valid_at_utc_s);
  return {};
}

std::string tile_data_problem(const MapTileHeader& t, std::span<const float> data, std::string_view pre) {
  const int nc = tile_value_count(t.channels, t.layer_channels);
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
    return line(pre, "data", "[", std::to_string(i), "] ", num(static_cast<double>(v)), " out of range [0, 1] (col ",
                std::to_string(texel % columns), ", row ", std::to_string(texel / columns), ", ", channel_name(t, static_cast<int>(i % nc)),
                ")");
  }
  return {};
}

#undef CHECK

}  // namespace cloudsvc::weather
