// Tileable 3D noise volumes for cloud shapes. See noise_volumes.h and docs/WEATHER.md.
//
// Construction (Schneider 2015, "The real-time volumetric cloudscapes of Horizon Zero
// Dawn"; Ford 2024 §4.2.2 describes the same Perlin-Worley / Worley textures). All positions are in units of the volume period, u in [0, 1)^3 at texel
// centres (i + 0.5) / size; every lattice and cell index is taken modulo its own period,
// so each volume tiles with period `size` texels.
//   perlin     = 0.5 + 0.5 * kPerlinGain * perlin_fbm(4 u; 4 octaves), clamped to [0, 1]
//   worley(f)  = 1 - min(1, Worley distance at f cells per period)     (inverted: billows)
//   wfbm(f)    = 0.625 worley(f) + 0.25 worley(2f) + 0.125 worley(4f)
//   pw         = remap(perlin, wfbm(4) - 1, 1, 0, 1)    Perlin dilated by Worley billows
//   base       = remap(pw, wfbm(8) - 1, 1, 0, 1)        shaped by finer Worley (Schneider's
//                                                       G, B, A channels, precombined)
//   detail     = wfbm(2) over its own period            (inverted Worley fBm, 2, 4, 8 cells)
// remap(v, lo, hi, a, b) = a + (v - lo) / (hi - lo) * (b - a). Finally each volume is
// stretched linearly so its 0.1 % and 99.9 % quantiles map to 0 and 255: the raw
// combinations occupy only part of [0, 1] (see the histograms in docs/WEATHER.md), and a
// full 8-bit range keeps quantisation steps small where the renderer thresholds the noise
// against coverage.
#include "weather/noise_volumes.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/parallel_for.h"
#include "weather/cellular_noise.h"
#include "weather/gradient_noise.h"
#include "weather/noise_hash.h"

namespace cloudsvc::weather {
namespace {

using detail::PeriodicWorley;

constexpr double kPerlinGain = 1.6;  // spreads the fBm's ~[-0.6, 0.6] over ~[-1, 1]

inline float remap(float v, float lo, float hi, float new_lo, float new_hi) {
  return new_lo + (v - lo) / (hi - lo) * (new_hi - new_lo);
}

// Three inverted Worley octaves at f, 2f, 4f cells per period with weights 0.625, 0.25,
// 0.125 (Schneider 2015), evaluated along a row of texels.
class WorleyFbm {
 public:
  WorleyFbm(int cells, std::uint32_t seed)
      : octaves_{PeriodicWorley(cells, detail::sub_seed(seed, 0)),
                 PeriodicWorley(2 * cells, detail::sub_seed(seed, 1)),
                 PeriodicWorley(4 * cells, detail::sub_seed(seed, 2))} {}

  // Row of `size` texel centres at period coordinates ((x + 0.5) / size, uy, uz).
  void row(int size, float uy, float uz, float* out, float* scratch) const {
    constexpr float kWeight[3] = {0.625f, 0.25f, 0.125f};
    std::fill(out, out + size, 0.0f);
    for (int o = 0; o < 3; ++o) {
      const float c = static_cast<float>(octaves_[o].cells());
      const float step = c / static_cast<float>(size);
      octaves_[o].distance_row(0.5f * step, step, size, uy * c, uz * c, scratch);
      for (int x = 0; x < size; ++x) out[x] += kWeight[o] * (1.0f - std::min(1.0f, scratch[x]));
    }
  }

 private:
  std::array<PeriodicWorley, 3> octaves_;
};

// Linear stretch of a float volume to 8 bits: quantile q_lo -> 0, q_hi -> 255.
std::vector<std::uint8_t> quantize_stretched(const std::vector<float>& v) {
  constexpr int kBins = 4096;
  float lo = v.empty() ? 0.0f : v[0], hi = lo;
  for (float x : v) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  float q_lo = lo, q_hi = hi;
  if (hi > lo) {
    std::vector<std::size_t> hist(kBins, 0);
    const float to_bin = (kBins - 1) / (hi - lo);
    for (float x : v) ++hist[static_cast<std::size_t>((x - lo) * to_bin)];
    const std::size_t n_lo = v.size() / 1000, n_hi = v.size() - v.size() / 1000;
    std::size_t acc = 0;
    int b_lo = -1, b_hi = kBins - 1;
    for (int b = 0; b < kBins; ++b) {
      acc += hist[b];
      if (b_lo < 0 && acc > n_lo) b_lo = b;
      if (acc >= n_hi) {
        b_hi = b;
        break;
      }
    }
    q_lo = lo + static_cast<float>(std::max(b_lo, 0)) / to_bin;
    q_hi = lo + static_cast<float>(b_hi + 1) / to_bin;
  }
  const float scale = q_hi > q_lo ? 255.0f / (q_hi - q_lo) : 0.0f;
  std::vector<std::uint8_t> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const float s = std::clamp((v[i] - q_lo) * scale, 0.0f, 255.0f);
    out[i] = static_cast<std::uint8_t>(std::lround(s));
  }
  return out;
}

// Fills a size^3 float volume row by row: row_fn(uy, uz, out) writes the `size` texels of
// the row at period coordinates ((x + 0.5) / size, uy, uz). z-slices are spread over
// all cores; row_fn must be safe to call concurrently.
template <typename RowFn>
std::vector<float> fill_volume(int size, const RowFn& row_fn) {
  const std::size_t n = static_cast<std::size_t>(size);
  std::vector<float> v(n * n * n);
  const float inv = 1.0f / static_cast<float>(size);
  parallel_for(size, kAllThreads, [&](int z) {
    const float uz = (static_cast<float>(z) + 0.5f) * inv;
    for (int y = 0; y < size; ++y) {
      const float uy = (static_cast<float>(y) + 0.5f) * inv;
      row_fn(uy, uz, &v[(static_cast<std::size_t>(z) * n + static_cast<std::size_t>(y)) * n]);
    }
  });
  return v;
}

}  // namespace

NoiseVolume make_base_shape_noise(int size, std::uint32_t seed) {
  NoiseVolume vol;
  vol.size = std::max(size, 0);
  if (vol.size == 0) return vol;
  constexpr int kPerlinCells = 4;  // lattice cells per period, lowest octave
  const detail::PerlinFbm perlin_fbm(4, kPerlinCells, detail::sub_seed(seed, 100));
  const WorleyFbm dilate(4, detail::sub_seed(seed, 101));
  const WorleyFbm shape(8, detail::sub_seed(seed, 102));
  const int n = vol.size;
  const std::vector<float> v = fill_volume(n, [&](float uy, float uz, float* out) {
    std::vector<float> w_dilate(n), w_shape(n), scratch(n);
    dilate.row(n, uy, uz, w_dilate.data(), scratch.data());
    shape.row(n, uy, uz, w_shape.data(), scratch.data());
    for (int x = 0; x < n; ++x) {
      const double ux = (x + 0.5) / n;
      const double p = perlin_fbm(ux * kPerlinCells, uy * kPerlinCells, uz * kPerlinCells);
      const float perlin =
          std::clamp(static_cast<float>(0.5 + 0.5 * kPerlinGain * p), 0.0f, 1.0f);
      const float pw = remap(perlin, w_dilate[x] - 1.0f, 1.0f, 0.0f, 1.0f);
      out[x] = remap(pw, w_shape[x] - 1.0f, 1.0f, 0.0f, 1.0f);
    }
  });
  vol.data = quantize_stretched(v);
  return vol;
}

NoiseVolume make_detail_noise(int size, std::uint32_t seed) {
  NoiseVolume vol;
  vol.size = std::max(size, 0);
  if (vol.size == 0) return vol;
  const WorleyFbm erosion(2, detail::sub_seed(seed, 200));
  const int n = vol.size;
  vol.data = quantize_stretched(fill_volume(n, [&](float uy, float uz, float* out) {
    std::vector<float> scratch(n);
    erosion.row(n, uy, uz, out, scratch.data());
  }));
  return vol;
}

double noise_mean(const NoiseVolume& v) {
  double sum = 0.0;
  for (std::uint8_t x : v.data) sum += x;
  return v.data.empty() ? 0.0 : sum / (255.0 * static_cast<double>(v.data.size()));
}

}  // namespace cloudsvc::weather
