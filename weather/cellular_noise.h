// Periodic Worley (cellular) noise (internal to weather/).
#pragma once

#include <cstdint>
#include <vector>

namespace cloudsvc::weather::detail {

// Worley noise (S. Worley, "A cellular texture basis function", SIGGRAPH 1996) with one
// uniformly random feature point in each cell of a cells^3 grid. The grid repeats with
// period `cells` along x, y and z (cell indices are taken modulo `cells`), so the noise
// tiles. Positions are in cell units: p in [0, cells) covers one period.
class PeriodicWorley {
 public:
  PeriodicWorley(int cells, std::uint32_t seed);

  // Distance, in cell widths, from p to the nearest feature point among the 27 cells
  // around p's cell; mostly 0..1. A point two cells away is at least 1 away, so the
  // result is exact whenever it is below 1 (callers clamp at 1).
  float distance(float x, float y, float z) const;

  // distance() at the `count` points (x0 + i * step, y, z), i = 0 .. count - 1, into out.
  // Same values as distance() up to float rounding, several times faster: the 27 candidate points are gathered
  // once per cell the row crosses and the search over them vectorises.
  void distance_row(float x0, float step, int count, float y, float z, float* out) const;

  int cells() const { return cells_; }

 private:
  int cells_;
  std::vector<float> points_;  // cells^3 * 3 offsets in [0, 1) within each cell
};

}  // namespace cloudsvc::weather::detail
