// Max pyramid of a tiling noise volume (see noise_max_pyramid.h).
#include "weather/noise_max_pyramid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cloudsvc::weather {

NoiseMaxPyramid::NoiseMaxPyramid(const NoiseVolume& v) : size_(v.size) {
  if (v.size <= 0 || (v.size & (v.size - 1)) != 0 ||
      v.data.size() != static_cast<std::size_t>(v.size) * v.size * v.size)
    throw std::invalid_argument("NoiseMaxPyramid: the volume's edge must be a power of two");
  levels_.push_back(v.data);
  for (int n = v.size / 2; n >= 1; n /= 2) {
    const std::vector<std::uint8_t>& f = levels_.back();
    const int m = n * 2;  // finer edge
    std::vector<std::uint8_t> c(static_cast<std::size_t>(n) * n * n);
    for (int z = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          std::uint8_t best = 0;
          for (int k = 0; k < 8; ++k) {
            const int fx = 2 * x + (k & 1), fy = 2 * y + ((k >> 1) & 1), fz = 2 * z + (k >> 2);
            best = std::max(best, f[(static_cast<std::size_t>(fz) * m + fy) * m + fx]);
          }
          c[(static_cast<std::size_t>(z) * n + y) * n + x] = best;
        }
    levels_.push_back(std::move(c));
  }
}

std::uint8_t NoiseMaxPyramid::cell(int level, int x, int y, int z) const {
  const int n = size_ >> level;
  const auto wrap = [n](int i) { return ((i % n) + n) % n; };
  return levels_[static_cast<std::size_t>(level)]
                [(static_cast<std::size_t>(wrap(z)) * n + wrap(y)) * n + wrap(x)];
}

double NoiseMaxPyramid::max_over(const glm::dvec3& u_lo, const glm::dvec3& u_hi) const {
  // Texels a trilinear sample at x = u n - 1/2 reads: floor(x) and floor(x) + 1.
  int lo[3], hi[3];
  int level = 0;
  for (int a = 0; a < 3; ++a) {
    // Reduce to a small range first (the box is short; its position only matters mod 1).
    const double shift = std::floor(u_lo[a]);
    const double x0 = (u_lo[a] - shift) * size_ - 0.5, x1 = (u_hi[a] - shift) * size_ - 0.5;
    if (!(x1 - x0 < size_)) return levels_.back()[0] / 255.0;  // spans a period: the global maximum
    lo[a] = static_cast<int>(std::floor(x0));
    hi[a] = static_cast<int>(std::floor(x1)) + 1;
    while ((hi[a] >> level) - (lo[a] >> level) > 1) ++level;  // arithmetic shifts floor negatives
  }
  if (level >= static_cast<int>(levels_.size())) return levels_.back()[0] / 255.0;
  std::uint8_t best = 0;
  for (int z = lo[2] >> level; z <= hi[2] >> level; ++z)
    for (int y = lo[1] >> level; y <= hi[1] >> level; ++y)
      for (int x = lo[0] >> level; x <= hi[0] >> level; ++x) best = std::max(best, cell(level, x, y, z));
  return best / 255.0;
}

}  // namespace cloudsvc::weather
