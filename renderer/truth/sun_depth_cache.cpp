// Cloud optical depth towards the sun per grid cell (see sun_depth_cache.h).
#include "renderer/truth/sun_depth_cache.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "renderer/truth/band_walker.h"

namespace cloudsvc::truth {

std::size_t SunDepthCache::CellHash::operator()(const Cell& c) const {
  // 64-bit mix of the three indices (the multipliers of Teschner et al. 2003, "Optimized
  // spatial hashing for collision detection of deformable objects", widened to 64 bits).
  const std::uint64_t h = static_cast<std::uint64_t>(c.i) * 73856093ull ^
                          static_cast<std::uint64_t>(c.j) * 19349663ull ^
                          static_cast<std::uint64_t>(c.k) * 83492791ull;
  return static_cast<std::size_t>(h ^ (h >> 29));
}

SunDepthCache::SunDepthCache(const TruthWorld& world, double cell_m, double cap)
    : world_(world), cell_m_(cell_m), cap_(cap) {
  if (!(cell_m > 0.0) || !(cap > 0.0)) throw std::invalid_argument("SunDepthCache: need cell_m > 0 and cap > 0");
  for (int a = 0; a < 3; ++a) corner_offset_[a] = world.sun[a] > 0.0 ? cell_m : 0.0;
}

double SunDepthCache::depth(const glm::dvec3& y) const {
  const Cell c{static_cast<std::int64_t>(std::floor(y.x / cell_m_)), static_cast<std::int64_t>(std::floor(y.y / cell_m_)),
               static_cast<std::int64_t>(std::floor(y.z / cell_m_))};
  Shard& shard = shards_[CellHash{}(c) % kShards];
  {
    const std::lock_guard<std::mutex> lock(shard.mutex);
    const auto it = shard.depths.find(c);
    if (it != shard.depths.end()) return it->second;
  }
  const double d = compute(c);  // outside the lock: a deterministic function of c
  const std::lock_guard<std::mutex> lock(shard.mutex);
  shard.depths.emplace(c, static_cast<float>(d));
  return static_cast<float>(d);
}

std::size_t SunDepthCache::cells() const {
  std::size_t n = 0;
  for (Shard& s : shards_) {
    const std::lock_guard<std::mutex> lock(s.mutex);
    n += s.depths.size();
  }
  return n;
}

double SunDepthCache::compute(const Cell& c) const {
  const glm::dvec3 x = glm::dvec3(static_cast<double>(c.i), static_cast<double>(c.j), static_cast<double>(c.k)) * cell_m_ +
                       corner_offset_;
  BandWalker walk(world_, x, world_.sun);
  MediumPoint m;
  double tau = 0.0, t_prev = 0.0, majorant = 0.0;
  std::uint64_t evals = 0;
  double result = kInfinity;
  for (;;) {
    if (evals == kMaxSteps) {
      result = tau;
      break;
    }
    const double t = walk.advance(1.0, majorant);
    if (t == kInfinity) {
      result = walk.end() == BandWalker::End::Ground ? kInfinity : tau;
      break;
    }
    const glm::dvec3 y = x + t * world_.sun;
    m = MediumPoint{};
    world_.medium->at(y, glm::length(y) - world_.radius_m, m);
    ++evals;
    // Right-point rule over the step's last stretch: advance() skips stretches whose
    // majorant is zero, which hold no cloud.
    tau += m.cloud_total() * std::min(t - t_prev, 1.0 / majorant);
    t_prev = t;
    if (tau >= cap_) {
      result = cap_;
      break;
    }
  }
  evals_ += evals;
  return std::min(result, cap_);
}

}  // namespace cloudsvc::truth
