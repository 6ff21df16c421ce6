// Tileable noise volumes (weather/noise_volumes.h): tiling, determinism, value spread.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "weather/noise_volumes.h"

namespace cloudsvc::weather {
namespace {

const NoiseVolume& base128() {
  static const NoiseVolume v = make_base_shape_noise(128, 1);
  return v;
}
const NoiseVolume& detail32() {
  static const NoiseVolume v = make_detail_noise(32, 2);
  return v;
}

int at(const NoiseVolume& v, int x, int y, int z) {
  return v.data[(static_cast<std::size_t>(z) * v.size + y) * v.size + x];
}

// Mean |difference| between neighbours along `axis` (0 = x, 1 = y, 2 = z): across the wrap
// (index size-1 -> 0) and between interior neighbours.
struct NeighbourDiff {
  double seam = 0.0, inside = 0.0;
};
NeighbourDiff neighbour_diff(const NoiseVolume& v, int axis) {
  const int n = v.size;
  const auto value = [&](int a, int b, int c) {  // c runs along the axis
    return axis == 0 ? at(v, c, a, b) : axis == 1 ? at(v, a, c, b) : at(v, a, b, c);
  };
  NeighbourDiff d;
  double inside_count = 0.0;
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      d.seam += std::abs(value(a, b, n - 1) - value(a, b, 0));
      for (int c = 0; c + 1 < n; ++c) {
        d.inside += std::abs(value(a, b, c + 1) - value(a, b, c));
        inside_count += 1.0;
      }
    }
  }
  d.seam /= static_cast<double>(n) * n;
  d.inside /= inside_count;
  return d;
}

void expect_tileable(const NoiseVolume& v, const char* name) {
  for (int axis = 0; axis < 3; ++axis) {
    const NeighbourDiff d = neighbour_diff(v, axis);
    EXPECT_GT(d.inside, 0.5) << name << ": volume is (nearly) constant";
    EXPECT_NEAR(d.seam / d.inside, 1.0, 0.3)
        << name << " axis " << axis << ": seam " << d.seam << " inside " << d.inside;
  }
}

TEST(NoiseVolumes, Sizes) {
  EXPECT_EQ(base128().size, 128);
  EXPECT_EQ(base128().data.size(), 128u * 128u * 128u);
  EXPECT_EQ(detail32().data.size(), 32u * 32u * 32u);
  EXPECT_TRUE(make_detail_noise(0, 1).data.empty());
}

TEST(NoiseVolumes, BaseShapeTiles) { expect_tileable(base128(), "base 128"); }
TEST(NoiseVolumes, DetailTiles) { expect_tileable(detail32(), "detail 32"); }
TEST(NoiseVolumes, OtherSizesTile) {
  expect_tileable(make_base_shape_noise(48, 5), "base 48");
  expect_tileable(make_detail_noise(40, 5), "detail 40");
}

// Sanity check of the tiling test itself: a volume cut out of a larger one (so it does not
// wrap) is caught.
TEST(NoiseVolumes, TilingCheckDetectsACutOutVolume) {
  const NoiseVolume big = make_detail_noise(64, 3);
  NoiseVolume cut;
  cut.size = 40;
  for (int z = 0; z < 40; ++z)
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) cut.data.push_back(static_cast<std::uint8_t>(at(big, x, y, z)));
  const NeighbourDiff d = neighbour_diff(cut, 0);
  EXPECT_GT(d.seam / d.inside, 1.3) << "seam " << d.seam << " inside " << d.inside;
}

TEST(NoiseVolumes, Deterministic) {
  EXPECT_EQ(make_base_shape_noise(32, 9).data, make_base_shape_noise(32, 9).data);
  EXPECT_EQ(make_detail_noise(32, 9).data, make_detail_noise(32, 9).data);
  EXPECT_EQ(make_base_shape_noise(128, 1).data, base128().data);
  const NoiseVolume a = make_base_shape_noise(32, 9), b = make_base_shape_noise(32, 10);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.data.size(); ++i) differing += a.data[i] != b.data[i];
  EXPECT_GT(differing, a.data.size() / 2) << "different seeds must give different noise";
  EXPECT_NE(make_detail_noise(32, 9).data, make_detail_noise(32, 10).data);
}

void expect_spread(const NoiseVolume& v, const char* name) {
  std::array<std::size_t, 16> hist{};
  double sum = 0.0;
  for (std::uint8_t x : v.data) {
    ++hist[x / 16];
    sum += x;
  }
  const double n = static_cast<double>(v.data.size());
  const double mean = sum / n;
  EXPECT_GT(mean, 90.0) << name;
  EXPECT_LT(mean, 170.0) << name;
  int populated = 0;  // bins holding at least 0.2 % of the voxels
  for (std::size_t c : hist) populated += c >= 0.002 * n;
  EXPECT_GE(populated, 14) << name;
  // Central 90 %: at least a third of the 8-bit range.
  std::size_t acc = 0;
  int p5 = -1, p95 = -1;
  std::array<std::size_t, 256> fine{};
  for (std::uint8_t x : v.data) ++fine[x];
  for (int i = 0; i < 256; ++i) {
    acc += fine[i];
    if (p5 < 0 && acc >= 0.05 * n) p5 = i;
    if (p95 < 0 && acc >= 0.95 * n) p95 = i;
  }
  EXPECT_GE(p95 - p5, 85) << name << ": p5 " << p5 << " p95 " << p95;
}

TEST(NoiseVolumes, ValuesSpreadOverTheRange) {
  expect_spread(base128(), "base 128");
  expect_spread(detail32(), "detail 32");
  expect_spread(make_base_shape_noise(64, 77), "base 64 seed 77");
}

}  // namespace
}  // namespace cloudsvc::weather
