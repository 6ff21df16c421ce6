// Perlin gradient noise and its fBm, optionally periodic (internal to weather/).
#pragma once

#include <cstdint>
#include <vector>

namespace cloudsvc::weather::detail {

// Perlin "improved" gradient noise (K. Perlin, "Improving noise", SIGGRAPH 2002): a
// pseudo-random gradient from the 12 cube-edge directions at each integer lattice point,
// blended with the quintic fade 6t^5 - 15t^4 + 10t^3 (C2-continuous). Zero at lattice
// points; values within about [-1, 1], standard deviation about 0.2.
// period > 0: lattice coordinates are reduced modulo `period` before hashing, so the noise
// tiles with that period along x, y and z. period <= 0: no tiling.
double perlin_noise(double x, double y, double z, int period, std::uint32_t seed);

// Fractal Brownian motion of perlin_noise: octave o (0-based) is evaluated at 2^o * p plus a
// per-octave offset (so the octaves' zero lattice points do not line up) with weight
// gain^o; the sum is divided by the sum of the weights. With period > 0 octave o tiles with
// period * 2^o lattice cells, i.e. the sum tiles with `period`. Octave seeds and offsets
// are derived from `seed` once, at construction; periodic octaves also tabulate their
// lattice gradients then (same values as perlin_noise, faster to read).
class PerlinFbm {
 public:
  static constexpr int kMaxOctaves = 12;
  PerlinFbm(int octaves, int period, std::uint32_t seed, double gain = 0.5);
  double operator()(double x, double y, double z) const;

 private:
  struct Octave {
    std::uint32_t seed = 0;
    int period = 0;
    double scale = 1, weight = 0, ox = 0, oy = 0, oz = 0;
    std::vector<std::uint8_t> grad;  // gradient index per lattice point, periodic octaves
  };
  int octaves_;
  Octave oct_[kMaxOctaves];
};

// One-off convenience form of PerlinFbm.
double perlin_fbm(double x, double y, double z, int octaves, int period, std::uint32_t seed,
                  double gain = 0.5);

}  // namespace cloudsvc::weather::detail
