// Weather-map flag values (map_flags.h).
#include "sim_client/map_flags.h"

#include <optional>

#include "common/option_values.h"
#include "protocol/messages.h"
#include "sim_client/text_input.h"

namespace cloudsvc::sim {

namespace {

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
    {"albedo", protocol::tile_channel::kGroundAlbedo},
};

}  // namespace

GeoBounds parse_flag_bounds(std::string_view flag, const std::string& text) {
  const auto parts = split(text, ',');
  const char* expected = "expected lat_min,lon_min,lat_max,lon_max in degrees, e.g. 40,0,50,20";
  if (parts.size() != 4) cli::fail(flag, text, expected);
  double v[4];
  for (int i = 0; i < 4; ++i) {
    const std::optional<double> x = cli::parse_finite_number(parts[static_cast<std::size_t>(i)]);
    if (!x) cli::fail(flag, text, expected);
    v[i] = *x;
  }
  GeoBounds b{v[0], v[1], v[2], v[3]};
  if (b.lat_min_deg < -90.0 || b.lat_max_deg > 90.0 || b.lat_min_deg >= b.lat_max_deg)
    cli::fail(flag, text, "latitudes must satisfy -90 <= lat_min < lat_max <= 90 (degrees)");
  if (b.lon_min_deg < -180.0 || b.lon_min_deg >= 180.0)
    cli::fail(flag, text, "lon_min must be in [-180, 180) (degrees)");
  if (b.lon_max_deg <= b.lon_min_deg || b.lon_max_deg > b.lon_min_deg + 360.0)
    cli::fail(flag, text,
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
      cli::fail(flag, text,
                "unknown channel '" + std::string(name) +
                    "' (expected a comma-separated list of coverage, development, density, precipitation, albedo)");
    for (std::uint8_t b : bits)
      if (b == *bit) cli::fail(flag, text, "channel " + channel_name(*bit) + " listed twice");
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
