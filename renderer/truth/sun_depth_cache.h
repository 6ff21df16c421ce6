// Where the ground truth's sun-guided copies are worth making (path_tracer.h): the cloud
// optical depth towards the sun, per cell of a cubic grid in the centred frame, computed
// the first time a path asks for a cell and kept for the rest of the frame.
//
// A copy is a second path drawn towards the sun to catch the droplets' forward peak; deep
// inside a cloud the sun is hidden and a copy only spends the camera path's copy budget.
// The tracer therefore guides only at points whose cell is shallow. The depth is a
// deterministic function of the cell (not of the random path), so a vertex's sampling
// strategies, and hence the MIS weights, are a function of its position and the path's
// history: the estimate stays unbiased whatever the depth's accuracy; an inaccurate depth
// costs variance or work, never bias.
//
// The depth of a cell is a quadrature of the cloud extinction (MediumPoint::cloud, 1/m)
// along the sun ray from the cell's corner nearest the sun (so that a cell's depth is about
// the smallest of its points'), in steps of one unit
// of majorant optical depth (BandWalker; stretches whose majorant is zero, clear of cloud,
// cost nothing and add nothing), until the ray leaves the top (the sum), reaches the
// depth `cap` (cap) or hits the ground (cap: the planet's shadow). A quadrature that
// would need more than kMaxSteps evaluations stops with the sum so far (an under-estimate:
// more guiding, never less).
//
// Thread-safe: cells are kept in sharded hash maps under a mutex each; two threads that
// compute the same cell at once store the same value.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <unordered_map>

#include <glm/glm.hpp>

#include "renderer/truth/truth_world.h"

namespace cloudsvc::truth {

class SunDepthCache {
 public:
  static constexpr int kMaxSteps = 512;

  // cell_m > 0: the grid's cell size (m); cap > 0: depths at or beyond it are returned as cap.
  SunDepthCache(const TruthWorld& world, double cell_m, double cap);

  // The cloud optical depth towards the sun of the cell holding y (centred frame, m).
  double depth(const glm::dvec3& y) const;

  std::size_t cells() const;                                  // cells computed so far
  std::uint64_t density_evals() const { return evals_.load(); }  // medium evaluations spent on them

 private:
  struct Cell {
    std::int64_t i, j, k;
    bool operator==(const Cell& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  struct Shard {
    std::mutex mutex;
    std::unordered_map<Cell, float, CellHash> depths;
  };
  static constexpr std::size_t kShards = 64;

  double compute(const Cell& c) const;

  const TruthWorld& world_;
  double cell_m_, cap_;
  glm::dvec3 corner_offset_;  // from a cell's minimum corner to its corner nearest the sun, m
  mutable std::array<Shard, kShards> shards_;
  mutable std::atomic<std::uint64_t> evals_{0};
};

}  // namespace cloudsvc::truth
