// Coverage max-pyramid of the weather map (issue 5: "nothing where the coverage
// max-pyramid, built on the CPU from the weather map, says the footprint is empty"). The
// march (shaders/coverage_pyramid.glsl) asks it, for each run of a few primary steps, for
// the largest coverage modulation m (channel r) anywhere the run's points can read the map;
// where even that m gives a layer local coverage 0 (local_coverage, weather/weather_map.h)
// the run has no cloud and its steps are skipped.
//
// Level 0 has one cell per bilinear footprint: cell (i, r) covers the map coordinates the
// GPU sampler interpolates from texel columns i and i + 1 (mod width) and texel rows r - 1
// and r (rows clamped; cell rows 0 and height also hold the pole value the shader blends to
// within half a row of a pole), i.e. x in [i + 1/2, i + 3/2) and y in [r - 1/2, r + 1/2)
// in texel units (texel (i, j) centred at (i + 1/2, j + 1/2)). Level k + 1 is the maximum of
// 2 x 2 cells of level k (a partial last row or column keeps what it has), up to 1 x 1. The
// value of each cell is the maximum over both weather keyframes (any blend of them stays
// below it) and counts a non-finite texel as full cloud. Conservative: bilinear
// interpolation, the pole blend and the keyframe blend never exceed the largest value they
// mix.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "weather/weather_map.h"

namespace cloudsvc {

struct CoveragePyramid {
  struct Level {
    int width = 0, height = 0;  // cells
    int offset = 0;             // index of the level's first cell in cells
  };
  std::vector<Level> levels;  // levels[0]: map width x (map height + 1) cells
  std::vector<float> cells;   // row-major per level, rows from the south

  bool empty() const { return levels.empty(); }
  float cell(int level, int i, int r) const {
    const Level& l = levels[static_cast<std::size_t>(level)];
    return cells[static_cast<std::size_t>(l.offset + r * l.width + i)];
  }
};

// The pyramid of map, or of the larger of map and next texel by texel (the two keyframes of
// a blend; next null: map alone). Throws std::invalid_argument if next's size differs.
CoveragePyramid build_coverage_pyramid(const weather::WeatherMap& map, const weather::WeatherMap* next = nullptr);

// Largest value the map can give anywhere within angular distance cap_rad (rad) of the
// direction at latitude lat_rad, longitude lon_rad (geocentric on the shell sphere, as the
// shader indexes the map): at most 3 x 3 cells of the finest level at which the cap spans
// that few, twice across the antimeridian. The CPU mirror of pyramid_max_in_cap in
// shaders/coverage_pyramid.glsl (tests hold the two to the same answer).
float pyramid_max_in_cap(const CoveragePyramid& p, double lat_rad, double lon_rad, double cap_rad);

// The pyramid as the std430 storage buffer shaders/coverage_pyramid.glsl reads, in 32-bit
// words: kGpuPyramidLevels ivec4 level records (width, height, offset; the first one's w:
// the level count), then the cells as floats. Empty if the pyramid is empty or has more
// levels than that (a map over 32768 texels a side): the march then does not use it.
constexpr int kGpuPyramidLevels = 16;
std::vector<std::uint32_t> pack_for_gpu(const CoveragePyramid& p);

}  // namespace cloudsvc
