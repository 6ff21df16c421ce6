// Periodic Worley noise. See cellular_noise.h.
#include "weather/cellular_noise.h"

#include <algorithm>
#include <cmath>

#include "weather/noise_hash.h"

namespace cloudsvc::weather::detail {

PeriodicWorley::PeriodicWorley(int cells, std::uint32_t seed) : cells_(std::max(1, cells)) {
  const int n = cells_;
  points_.resize(static_cast<std::size_t>(n) * n * n * 3);
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const std::uint32_t h = hash_cell(x, y, z, seed);
        const std::size_t i = (static_cast<std::size_t>(z) * n + y) * n + x;
        points_[3 * i + 0] = hash_to_unit(h);
        points_[3 * i + 1] = hash_to_unit(hash32(h ^ 0x5bd1e995U));
        points_[3 * i + 2] = hash_to_unit(hash32(h ^ 0x1b873593U));
      }
    }
  }
}

float PeriodicWorley::distance(float x, float y, float z) const {
  const int n = cells_;
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
  const float rx = x - fx, ry = y - fy, rz = z - fz;  // position within the centre cell
  // Cell indices of the three neighbours per axis, modulo n (one division per axis).
  const auto neighbours = [n](int i, int w[3]) {
    const int m = i % n;
    w[1] = m < 0 ? m + n : m;
    w[0] = w[1] == 0 ? n - 1 : w[1] - 1;
    w[2] = w[1] + 1 == n ? 0 : w[1] + 1;
  };
  int wx[3], wy[3], wz[3];
  neighbours(ix, wx);
  neighbours(iy, wy);
  neighbours(iz, wz);
  // A bounding-box test that skips far cells was tried: the branches cost more than the
  // ~20 multiply-adds they save.
  float best = 1e30f;
  for (int dz = 0; dz < 3; ++dz) {
    for (int dy = 0; dy < 3; ++dy) {
      const std::size_t row = (static_cast<std::size_t>(wz[dz]) * n + wy[dy]) * n;
      for (int dx = 0; dx < 3; ++dx) {
        const float* p = &points_[3 * (row + wx[dx])];
        // Feature point relative to p, in cells.
        const float ex = static_cast<float>(dx - 1) + p[0] - rx;
        const float ey = static_cast<float>(dy - 1) + p[1] - ry;
        const float ez = static_cast<float>(dz - 1) + p[2] - rz;
        best = std::min(best, ex * ex + ey * ey + ez * ez);
      }
    }
  }
  return std::sqrt(best);
}

void PeriodicWorley::distance_row(float x0, float step, int count, float y, float z,
                                  float* out) const {
  const int n = cells_;
  const auto wrap = [n](int i) {
    const int m = i % n;
    return m < 0 ? m + n : m;
  };
  const float fy = std::floor(y), fz = std::floor(z);
  const int iy = static_cast<int>(fy), iz = static_cast<int>(fz);
  const float ry = y - fy, rz = z - fz;
  // Candidates of the current cell, relative to its origin, structure of arrays.
  alignas(16) float cx[27], cy[27], cz[27];
  int cell = 0;
  bool have = false;
  for (int i = 0; i < count; ++i) {
    const float x = x0 + step * static_cast<float>(i);
    const float fx = std::floor(x);
    const int ix = static_cast<int>(fx);
    if (!have || ix != cell) {
      cell = ix;
      have = true;
      int k = 0;
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          const std::size_t row =
              (static_cast<std::size_t>(wrap(iz + dz)) * n + wrap(iy + dy)) * n;
          for (int dx = -1; dx <= 1; ++dx, ++k) {
            const float* p = &points_[3 * (row + wrap(ix + dx))];
            cx[k] = static_cast<float>(dx) + p[0];
            cy[k] = static_cast<float>(dy) + p[1] - ry;
            cz[k] = static_cast<float>(dz) + p[2] - rz;
          }
        }
      }
      // y and z are fixed along the row: fold their squared terms in once.
      for (k = 0; k < 27; ++k) cz[k] = cy[k] * cy[k] + cz[k] * cz[k];
    }
    const float rx = x - fx;
    float best = 1e30f;
    for (int k = 0; k < 27; ++k) {
      const float ex = cx[k] - rx;
      best = std::min(best, ex * ex + cz[k]);
    }
    out[i] = std::sqrt(best);
  }
}

}  // namespace cloudsvc::weather::detail
