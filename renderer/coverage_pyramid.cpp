#include "renderer/coverage_pyramid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace cloudsvc {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Conservative value of one texel: non-finite counts as full cloud.
float texel_bound(float v) { return std::isfinite(v) ? v : 1.0f; }

// Largest cell of level k over cells [i0, i1] x [r0, r1] (no wrap; all in range).
float max_over(const CoveragePyramid& p, int k, int i0, int i1, int r0, int r1) {
  float m = 0.0f;
  for (int r = r0; r <= r1; ++r)
    for (int i = i0; i <= i1; ++i) m = std::max(m, p.cell(k, i, r));
  return m;
}

// Level-0 cell ranges [i0, i1] x [r0, r1] (i0 <= i1 < width) read at the finest level at
// which they span at most three cells per axis.
float max_in_range(const CoveragePyramid& p, int i0, int i1, int r0, int r1) {
  const int top = static_cast<int>(p.levels.size()) - 1;
  int k = 0;
  while (k < top && ((i1 >> k) - (i0 >> k) > 2 || (r1 >> k) - (r0 >> k) > 2)) ++k;
  return max_over(p, k, i0 >> k, i1 >> k, r0 >> k, r1 >> k);
}
}  // namespace

CoveragePyramid build_coverage_pyramid(const weather::WeatherMap& map, const weather::WeatherMap* next) {
  CoveragePyramid p;
  const int W = map.width, H = map.height;
  if (W <= 0 || H <= 0 || map.rgba.size() < static_cast<size_t>(W) * H * 4) return p;
  if (next && (next->width != W || next->height != H || next->rgba.size() < map.rgba.size()))
    throw std::invalid_argument("build_coverage_pyramid: keyframes of different sizes");
  // texel maximum over the keyframes, and the pole values (row means) of each
  std::vector<float> texel(static_cast<size_t>(W) * H);
  for (size_t n = 0; n < texel.size(); ++n) {
    float v = map.coverage_bound(n);
    if (next) v = std::max(v, next->coverage_bound(n));
    texel[n] = v;
  }
  float pole[2] = {0.0f, 0.0f};  // south, north
  // the poles' values bounded as coverage_bound bounds a texel: R and the layer-coverage channels
  const auto pole_bound = [](const weather::WeatherMap& m, bool north) {
    float v[4], c[4];
    m.pole_value(north, v);
    m.layer_coverage_pole_value(north, c);
    float b = texel_bound(v[0]);
    if (m.has_layer_coverage())
      for (float x : c) b = std::max(b, texel_bound(x));
    return b;
  };
  for (int north = 0; north < 2; ++north) {
    pole[north] = pole_bound(map, north != 0);
    if (next) pole[north] = std::max(pole[north], pole_bound(*next, north != 0));
  }
  // level 0: cell (i, r) = texel columns i, i + 1 (mod W) x texel rows r - 1, r (clamped)
  CoveragePyramid::Level l0{W, H + 1, 0};
  p.levels.push_back(l0);
  p.cells.assign(static_cast<size_t>(W) * (H + 1), 0.0f);
  std::vector<float> rows(static_cast<size_t>(W));  // max of the cell row's two texel rows
  for (int r = 0; r <= H; ++r) {
    const float* lo = &texel[static_cast<size_t>(std::max(r - 1, 0)) * W];
    const float* hi = &texel[static_cast<size_t>(std::min(r, H - 1)) * W];
    for (int i = 0; i < W; ++i) rows[static_cast<size_t>(i)] = std::max(lo[i], hi[i]);
    float* out = &p.cells[static_cast<size_t>(r) * W];
    for (int i = 0; i + 1 < W; ++i) out[i] = std::max(rows[static_cast<size_t>(i)], rows[static_cast<size_t>(i) + 1]);
    out[W - 1] = std::max(rows[static_cast<size_t>(W) - 1], rows[0]);
    if (r == 0 || r == H)  // the rows the shader blends towards a pole's value
      for (int i = 0; i < W; ++i) out[i] = std::max(out[i], pole[r == 0 ? 0 : 1]);
  }
  // coarser levels: 2 x 2 maxima up to a single cell
  while (p.levels.back().width > 1 || p.levels.back().height > 1) {
    const CoveragePyramid::Level prev = p.levels.back();
    const CoveragePyramid::Level l{(prev.width + 1) / 2, (prev.height + 1) / 2, static_cast<int>(p.cells.size())};
    p.levels.push_back(l);
    p.cells.resize(p.cells.size() + static_cast<size_t>(l.width) * l.height, 0.0f);
    for (int r = 0; r < l.height; ++r) {
      const float* a = &p.cells[static_cast<size_t>(prev.offset + 2 * r * prev.width)];
      const float* b = &p.cells[static_cast<size_t>(prev.offset + std::min(2 * r + 1, prev.height - 1) * prev.width)];
      float* out = &p.cells[static_cast<size_t>(l.offset + r * l.width)];
      for (int i = 0; i < l.width; ++i) {
        const int i1 = std::min(2 * i + 1, prev.width - 1);
        out[i] = std::max(std::max(a[2 * i], a[i1]), std::max(b[2 * i], b[i1]));
      }
    }
  }
  return p;
}

float pyramid_max_in_cap(const CoveragePyramid& p, double lat_rad, double lon_rad, double cap_rad) {
  if (p.empty()) return 1.0f;  // no map: nothing is known to be clear
  const int W = p.levels[0].width, H = p.levels[0].height - 1;
  // A sampler's texel weights carry a few bits of sub-texel precision: the ranges are
  // widened by 1/16 texel so that a point on a cell edge counts both cells.
  constexpr double kEdge = 1.0 / 16.0;
  const double y_lo = ((lat_rad - cap_rad) / kPi + 0.5) * H - kEdge;
  const double y_hi = ((lat_rad + cap_rad) / kPi + 0.5) * H + kEdge;
  const int r0 = std::clamp(static_cast<int>(std::floor(y_lo + 0.5)), 0, H);
  const int r1 = std::clamp(static_cast<int>(std::floor(y_hi + 0.5)), 0, H);
  // longitude extent of the cap: asin(sin a / cos lat); all longitudes over a pole
  const double s = std::sin(cap_rad) / std::cos(lat_rad);
  if (lat_rad - cap_rad <= -0.5 * kPi || lat_rad + cap_rad >= 0.5 * kPi || !(s < 1.0))
    return max_in_range(p, 0, W - 1, r0, r1);
  const double dl = std::asin(s);
  const double x_lo = ((lon_rad - dl) / (2.0 * kPi) + 0.5) * W - kEdge;
  const double x_hi = ((lon_rad + dl) / (2.0 * kPi) + 0.5) * W + kEdge;
  int i0 = static_cast<int>(std::floor(x_lo - 0.5)), i1 = static_cast<int>(std::floor(x_hi - 0.5));
  if (i1 - i0 + 1 >= W) return max_in_range(p, 0, W - 1, r0, r1);
  // i0 into [0, W): lon in [-pi, pi] and dl <= pi / 2 put i0 in [-W / 4 - 1, W)
  if (i0 < 0) { i0 += W; i1 += W; }
  if (i0 >= W) { i0 -= W; i1 -= W; }
  if (i1 < W) return max_in_range(p, i0, i1, r0, r1);
  return std::max(max_in_range(p, i0, W - 1, r0, r1), max_in_range(p, 0, i1 - W, r0, r1));
}

std::vector<std::uint32_t> pack_for_gpu(const CoveragePyramid& p) {
  if (p.empty() || p.levels.size() > static_cast<size_t>(kGpuPyramidLevels)) return {};
  std::vector<std::uint32_t> words(4 * kGpuPyramidLevels + p.cells.size(), 0u);
  for (size_t k = 0; k < p.levels.size(); ++k) {
    words[4 * k] = static_cast<std::uint32_t>(p.levels[k].width);
    words[4 * k + 1] = static_cast<std::uint32_t>(p.levels[k].height);
    words[4 * k + 2] = static_cast<std::uint32_t>(p.levels[k].offset);
  }
  words[3] = static_cast<std::uint32_t>(p.levels.size());
  std::memcpy(&words[4 * kGpuPyramidLevels], p.cells.data(), p.cells.size() * sizeof(float));
  return words;
}

}  // namespace cloudsvc
