// Splitting a weather-map raster into protocol tiles (map_tiles.h).
#include "sim_client/map_tiles.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace cloudsvc::sim {

namespace {

// Bytes of a WeatherMapTile message besides its float data (fields, vtable, envelope,
// frame header), rounded up generously.
constexpr std::uint64_t kTileOverheadBytes = 1024;

// Boundary k of n parts of `size` texels.
int boundary(int k, int n, int size) {
  return static_cast<int>(static_cast<long long>(k) * size / n);
}

// Edge coordinate of texel boundary c in [0, size] between lo and hi (exactly hi at size).
double edge(int c, int size, double lo, double hi) {
  return c == size ? hi : lo + static_cast<double>(c) * (hi - lo) / static_cast<double>(size);
}

}  // namespace

std::size_t MapRaster::value_count() const {
  return channel_bits.size() + static_cast<std::size_t>(std::popcount(static_cast<unsigned>(layer_channels)));
}

std::vector<protocol::WeatherMapTile> split_into_tiles(const MapRaster& raster, const GeoBounds& bounds,
                                                       double valid_at_utc_s, std::uint32_t max_side) {
  const std::size_t nc = raster.value_count();
  if (raster.width < 1 || raster.height < 1 || nc < 1 || raster.channel_bits.size() > 5 ||
      (raster.layer_channels & ~0x0fu))
    throw std::invalid_argument("weather map: need at least 1x1 texels, 0..5 channels and layer slots 0..3, not none");
  if (raster.values.size() != static_cast<std::size_t>(raster.width) * raster.height * nc)
    throw std::invalid_argument("weather map: value count does not match width x height x channels");
  if (max_side < 1) throw std::invalid_argument("weather map: tile side must be at least 1 texel");
  std::uint8_t all_bits = 0;
  for (std::uint8_t b : raster.channel_bits) {
    if (b == 0 || (b & (b - 1)) != 0 || (b & all_bits) || (b & ~protocol::tile_channel::kAll))
      throw std::invalid_argument("weather map: channel bits must be distinct single tile_channel bits");
    all_bits |= b;
  }
  // order[k]: raster value holding the tile's k-th value (channels in ascending bit order,
  // then the layer slots as they are).
  std::vector<std::size_t> order(nc);
  for (std::size_t k = 0; k < nc; ++k) order[k] = k;
  std::sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(raster.channel_bits.size()),
            [&](std::size_t a, std::size_t b) { return raster.channel_bits[a] < raster.channel_bits[b]; });

  const int side = static_cast<int>(std::min<std::uint32_t>(max_side, 1u << 30));
  const int nx = (raster.width + side - 1) / side;
  const int ny = (raster.height + side - 1) / side;
  std::vector<protocol::WeatherMapTile> tiles;
  tiles.reserve(static_cast<std::size_t>(nx) * ny);
  // Tile rows counted from the south: tile row j covers south-first rows [s0, s1).
  for (int j = 0; j < ny; ++j) {
    const int s0 = boundary(j, ny, raster.height), s1 = boundary(j + 1, ny, raster.height);
    for (int i = 0; i < nx; ++i) {
      const int c0 = boundary(i, nx, raster.width), c1 = boundary(i + 1, nx, raster.width);
      protocol::WeatherMapTile t;
      t.lat_min_deg = edge(s0, raster.height, bounds.lat_min_deg, bounds.lat_max_deg);
      t.lat_max_deg = edge(s1, raster.height, bounds.lat_min_deg, bounds.lat_max_deg);
      t.lon_min_deg = edge(c0, raster.width, bounds.lon_min_deg, bounds.lon_max_deg);
      t.lon_max_deg = edge(c1, raster.width, bounds.lon_min_deg, bounds.lon_max_deg);
      if (t.lon_min_deg >= 180.0) {
        t.lon_min_deg -= 360.0;
        t.lon_max_deg -= 360.0;
      }
      t.width = static_cast<std::uint32_t>(c1 - c0);
      t.height = static_cast<std::uint32_t>(s1 - s0);
      t.channels = all_bits;
      t.layer_channels = raster.layer_channels;
      t.valid_at_utc_s = valid_at_utc_s;
      t.data.resize(static_cast<std::size_t>(t.width) * t.height * nc);
      std::size_t out = 0;
      for (int s = s0; s < s1; ++s) {
        const int image_row = raster.height - 1 - s;  // south-first -> north-first
        for (int c = c0; c < c1; ++c) {
          const float* texel = &raster.values[(static_cast<std::size_t>(image_row) * raster.width + c) * nc];
          for (std::size_t k = 0; k < nc; ++k) t.data[out++] = texel[order[k]];
        }
      }
      tiles.push_back(std::move(t));
    }
  }
  return tiles;
}

std::uint32_t tile_side_for(const protocol::Limits& limits, int channels) {
  const std::uint64_t per_texel = 4ull * static_cast<std::uint64_t>(std::max(channels, 1));  // bytes
  const std::uint64_t budget = limits.max_payload_bytes > kTileOverheadBytes ? limits.max_payload_bytes - kTileOverheadBytes : 0;
  auto side = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(budget / per_texel)));
  while (side * side * per_texel > budget) --side;  // sqrt rounding
  side = std::min<std::uint64_t>(side, limits.max_tile_size);
  return static_cast<std::uint32_t>(std::max<std::uint64_t>(side, 1));
}

}  // namespace cloudsvc::sim
