// Tileable 3D noise volumes for cloud shapes (Schneider, "The real-time volumetric
// cloudscapes of Horizon Zero Dawn", 2015; Ford 2024 §4.2.2): generated once at start-up,
// deterministically from a seed.
#pragma once

#include <cstdint>
#include <vector>

namespace cloudsvc::weather {

struct NoiseVolume {
  int size = 0;                // cube edge, texels
  std::vector<std::uint8_t> data;  // size^3 values, x fastest, then y, then z; 0..255 -> [0, 1]
};

// Base shape: Perlin-Worley (Perlin fBm remapped by inverted Worley fBm), further shaped
// by three Worley octaves, precombined into one channel. Tiles with period `size`.
NoiseVolume make_base_shape_noise(int size = 128, std::uint32_t seed = 1);
// Detail erosion: three octaves of inverted Worley noise, one channel. Tiles.
// Both volumes are stretched so their 0.1 % / 99.9 % quantiles map to 0 / 255; formulas,
// histograms and timings are in docs/WEATHER.md. Generation uses all cores
// (common/parallel_for.h); the volumes do not depend on the thread count.
NoiseVolume make_detail_noise(int size = 32, std::uint32_t seed = 2);

// Mean value of a volume, in [0, 1].
double noise_mean(const NoiseVolume& v);

}  // namespace cloudsvc::weather
