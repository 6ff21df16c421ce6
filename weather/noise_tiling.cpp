#include "weather/noise_tiling.h"

#include <algorithm>
#include <cmath>

#include "weather/noise_hash.h"

namespace cloudsvc::weather {

std::uint32_t base_tiling_seed(std::uint32_t noise_seed, CloudType type) {
  return detail::sub_seed(detail::sub_seed(noise_seed, 0x711e0000U), static_cast<std::uint32_t>(type));
}

std::uint32_t detail_tiling_seed(std::uint32_t noise_seed, CloudType type) {
  return detail::sub_seed(detail::sub_seed(noise_seed, 0x711e0001U), static_cast<std::uint32_t>(type));
}

std::uint32_t tiling_lattice_seed(std::uint32_t seed, int k) {
  return detail::sub_seed(seed, static_cast<std::uint32_t>(k));
}

glm::dvec3 tiling_offset(const glm::ivec3& cell, std::uint32_t lattice_seed) {
  const auto u = [](std::int32_t c) { return static_cast<std::uint32_t>(c); };
  const std::uint32_t h =
      detail::hash32((u(cell.x) * 0x8da6b343U) ^ (u(cell.y) * 0xd8163841U) ^ (u(cell.z) * 0xcb1ab31fU) ^ lattice_seed);
  return glm::dvec3(h & 1023U, (h >> 10) & 1023U, (h >> 20) & 1023U) / 1024.0;
}

double tiling_weight(const glm::dvec3& x) {
  double w = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double t = (x[a] - std::floor(x[a]) - kTilingFaceBand) / (1.0 - 2.0 * kTilingFaceBand);
    const double b = std::max(4.0 * t * (1.0 - t), 0.0);
    w *= b * b;
  }
  return w;
}

namespace {

// the per-axis factor of tiling_weight at u = frac(x)
double axis_bump(double u) {
  const double t = (u - kTilingFaceBand) / (1.0 - 2.0 * kTilingFaceBand);
  const double b = std::max(4.0 * t * (1.0 - t), 0.0);
  return b * b;
}

}  // namespace

glm::dvec2 tiling_weight_range(const glm::dvec3& x_lo, const glm::dvec3& x_hi) {
  glm::dvec2 w(1.0);
  for (int a = 0; a < 3; ++a) {
    if (x_hi[a] - x_lo[a] >= 1.0) {
      w.x = 0.0;  // a face and a centre inside
      continue;
    }
    // the bump rises to its centre u = 1/2 and falls after it, within each cell
    const double u0 = x_lo[a] - std::floor(x_lo[a]), u1 = u0 + (x_hi[a] - x_lo[a]);
    const double b0 = axis_bump(u0), b1 = axis_bump(u1 >= 1.0 ? u1 - 1.0 : u1);
    const bool centre = (u0 <= 0.5 && u1 >= 0.5) || u1 >= 1.5;
    w.x *= u1 >= 1.0 ? 0.0 : std::min(b0, b1);
    w.y *= centre ? 1.0 : std::max(b0, b1);
  }
  return w;
}

double tiled_max_over(const NoiseMaxPyramid& pyramid, const glm::dvec3& lo, const glm::dvec3& hi, std::uint32_t seed,
                      double mean) {
  std::array<double, kTilingLattices> m{};
  std::array<glm::dvec2, kTilingLattices> w{};
  for (int k = 0; k < kTilingLattices; ++k) {
    w[k] = tiling_weight_range(lo - 0.25 * k, hi - 0.25 * k);
    // the cells whose weighted cores (c + b, c + 1 - b) the box's interval touches, per axis
    const glm::dvec3 c_min = glm::floor(lo - 0.25 * k + kTilingFaceBand);
    const glm::dvec3 c_max = glm::ceil(hi - 0.25 * k - kTilingFaceBand) - 1.0;
    if (c_min.x > c_max.x || c_min.y > c_max.y || c_min.z > c_max.z) continue;  // no weight in the box
    if (c_min != c_max) return 1.0;  // several cells, several offsets
    const glm::dvec3 o = tiling_offset(glm::ivec3(c_min), tiling_lattice_seed(seed, k));
    m[k] = pyramid.max_over(lo + o, hi + o);
  }
  return tiling_bound(m, w, mean);
}

double tiling_bound(const std::array<double, kTilingLattices>& m, const std::array<glm::dvec2, kTilingLattices>& w,
                    double mean) {
  double largest = 0.0, above2 = 0.0, num = 0.0, den2 = 0.0;
  for (int k = 0; k < kTilingLattices; ++k) {
    const double a = std::max(m[k] - mean, 0.0);
    largest = std::max(largest, m[k]);
    above2 += a * a;
    num += w[k].y * a;
    den2 += w[k].x * w[k].x;
  }
  if (largest <= mean) return largest;
  const double gain = den2 > 0.0 ? std::min(std::sqrt(above2), num / std::sqrt(den2)) : std::sqrt(above2);
  return std::min(1.0, mean + gain);
}

}  // namespace cloudsvc::weather
