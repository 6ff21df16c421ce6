#include "weather/cloud_placement.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "weather/noise_hash.h"

namespace cloudsvc::weather {
namespace {


// The expected number of discs over a point, sum_k p_k pi <rho^2>, for the level
// probabilities p_k = min(1, P w_k): with the clouds' centres taken as a Poisson process the
// covered fraction is 1 - exp(-this).
double coverage_depth(double P, const std::vector<double>& w, double disc_fraction) {
  double s = 0.0;
  for (double wk : w) s += std::min(1.0, P * wk) * disc_fraction;
  return s;
}

}  // namespace

CloudPlacement::CloudPlacement(const PlacementParams& params, double shell_radius_m, std::uint32_t seed)
    : params_(params), R_(shell_radius_m), seed_(seed) {
  if (!(params.smallest_cell_m > 0.0) || params.levels < 1 || params.levels > 16)
    throw std::invalid_argument("cloud placement: smallest cell must be > 0 m and levels 1..16");
  if (!(params.size_exponent > 0.0 && params.size_exponent < 3.0))
    throw std::invalid_argument("cloud placement: size exponent must be in (0, 3)");
  if (!(params.rho_min > 0.0 && params.rho_min <= params.rho_max && params.rho_max <= 0.5))
    throw std::invalid_argument("cloud placement: need 0 < rho_min <= rho_max <= 0.5");
  if (!(shell_radius_m > 0.0)) throw std::invalid_argument("cloud placement: shell radius must be > 0");
  const double a = params.rho_min, b = params.rho_max;
  mean_rho2_ = b > a ? (b * b * b - a * a * a) / (3.0 * (b - a)) : a * a;
  level_weight_.resize(static_cast<std::size_t>(params.levels));
  for (int k = 0; k < params.levels; ++k) level_weight_[k] = std::pow(2.0, k * (2.0 - 2.0 * params.size_exponent));
  const double wmax = *std::max_element(level_weight_.begin(), level_weight_.end());
  for (double& w : level_weight_) w /= wmax;
  acceptance_table_.reserve(static_cast<std::size_t>(kCoverageSteps + 1) * params.levels);
  for (int i = 0; i <= kCoverageSteps; ++i)
    for (double p : acceptance(static_cast<double>(i) / kCoverageSteps)) acceptance_table_.push_back(p);
}

std::uint32_t CloudPlacement::level_seed(int level) const {
  return detail::sub_seed(seed_, static_cast<std::uint32_t>(level));
}

double CloudPlacement::level_acceptance(int level, double coverage) const {
  const double x = std::clamp(coverage, 0.0, 1.0) * kCoverageSteps;
  const int i = std::min(static_cast<int>(x), kCoverageSteps - 1);
  const double f = x - i;
  const std::size_t L = static_cast<std::size_t>(params_.levels);
  return (1.0 - f) * acceptance_table_[i * L + level] + f * acceptance_table_[(i + 1) * L + level];
}

double CloudPlacement::max_coverage() const {
  return -std::expm1(-coverage_depth(1e30, level_weight_, std::numbers::pi * mean_rho2_));
}

std::vector<double> CloudPlacement::acceptance(double coverage) const {
  const double disc = std::numbers::pi * mean_rho2_;
  const double c = std::clamp(coverage, 0.0, max_coverage());
  const double target = -std::log1p(-c);
  // P from 0 to the value that makes every level certain (1 / the smallest weight)
  double lo = 0.0, hi = 1.0 / *std::min_element(level_weight_.begin(), level_weight_.end());
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (coverage_depth(mid, level_weight_, disc) < target ? lo : hi) = mid;
  }
  std::vector<double> p(level_weight_.size());
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = std::min(1.0, hi * level_weight_[k]);
  return p;
}

double CloudPlacement::covered_below(int first_level, double coverage) const {
  double depth = 0.0;
  for (int k = 0; k < std::min(first_level, params_.levels); ++k)
    depth += level_acceptance(k, coverage) * std::numbers::pi * mean_rho2_;
  return -std::expm1(-depth);
}

template <class Want, class F>
void CloudPlacement::for_each_nearby_cloud(const glm::dvec3& x, const CoverageAt& coverage, int first, int end,
                                           Want&& want, F&& f) const {
  using detail::hash32;
  using detail::hash_cell;
  using detail::hash_to_unit;
  for (int k = std::max(first, 0); k < std::min(end, params_.levels); ++k) {
    const double s = params_.smallest_cell_m * std::ldexp(1.0, k);
    const glm::dvec3 cell = glm::floor(x / s);
    const std::uint32_t seed_k = level_seed(k);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::int32_t ix = static_cast<std::int32_t>(cell.x) + dx, iy = static_cast<std::int32_t>(cell.y) + dy,
                             iz = static_cast<std::int32_t>(cell.z) + dz;
          const std::uint32_t h = hash_cell(ix, iy, iz, seed_k);
          const glm::dvec3 q = (glm::dvec3(ix, iy, iz) +
                                glm::dvec3(hash_to_unit(hash32(h ^ 0x1u)), hash_to_unit(hash32(h ^ 0x2u)),
                                           hash_to_unit(hash32(h ^ 0x3u)))) *
                               s;
          const double rq = glm::length(q);
          if (!(std::abs(rq - R_) < 0.5 * s)) continue;  // outside the slab around the shell
          const glm::dvec3 centre = q * (R_ / rq);
          const double rho = params_.rho_min + (params_.rho_max - params_.rho_min) * hash_to_unit(hash32(h ^ 0x5u));
          const double r = rho * s;
          if (!want(centre, r)) continue;
          // acceptance at the cloud's own centre (exists or not as a whole), asked last: it
          // may read the weather map
          if (!(hash_to_unit(hash32(h ^ 0x4u)) < level_acceptance(k, coverage(centre)))) continue;
          f(k, centre, r, h);
        }
  }
}

void CloudPlacement::clouds_at(const glm::dvec3& x, const CoverageAt& coverage, std::vector<PlacedCloud>& out,
                               int first_level) const {
  const auto covers_x = [&](const glm::dvec3& centre, double r) { return glm::length(x - centre) < r; };
  for_each_nearby_cloud(x, coverage, first_level, params_.levels, covers_x,
                        [&](int k, const glm::dvec3& centre, double r, std::uint32_t h) {
                          out.push_back({centre, r, k, h});
                        });
}

double CloudPlacement::envelope(const glm::dvec3& x, const CoverageAt& coverage, int first_level) const {
  double e = 0.0;
  const auto covers_x = [&](const glm::dvec3& centre, double r) { return glm::length(x - centre) < r; };
  for_each_nearby_cloud(x, coverage, first_level, params_.levels, covers_x,
                        [&](int, const glm::dvec3& centre, double r, std::uint32_t) {
                          const double u = glm::length(x - centre) / r;
                          e = std::max(e, 1.0 - u * u);
                        });
  return e;
}

double CloudPlacement::dome_top(const glm::dvec3& x, const CoverageAt& coverage, int first_level, int end_level,
                                double floor_m) const {
  double top = -floor_m;
  const auto dome = [&](const glm::dvec3& centre, double r) {
    const glm::dvec3 d = x - centre;
    return (r * r - glm::dot(d, d)) / r;
  };
  // only candidates that would raise the top ask for their acceptance
  for_each_nearby_cloud(x, coverage, first_level, end_level,
                        [&](const glm::dvec3& centre, double r) { return dome(centre, r) > top; },
                        [&](int, const glm::dvec3& centre, double r, std::uint32_t) { top = dome(centre, r); });
  return top;
}

}  // namespace cloudsvc::weather
