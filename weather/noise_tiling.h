// Stochastic tiling of a periodic noise volume (after Heitz & Neyret 2018, "High-Performance
// By-Example Noise using a Histogram-Preserving Blending Operator", and Deliot & Heitz 2019,
// "Procedural Stochastic Textures by Tiling and Blending", here in 3-D): a noise volume
// tiles with its period P, so a field read from it alone repeats every P in every
// direction (docs/MORPHOLOGY.md). Instead, space is covered by four cubic lattices of cells
// of edge P, lattice k shifted by k/4 of a cell along the diagonal; every cell reads the
// volume at its own random offset, and a point blends the cells that hold it:
//
//   s = field position / P (periods); per lattice k: u = frac(s - k/4) per axis,
//   cell_k = floor(s - k/4), t = (u - b) / (1 - 2 b) with the face band b = kTilingFaceBand,
//   w_k = prod_axes max(4 t (1 - t), 0)^2   (0 within b of the cell's faces, 1 at its centre)
//   x_k = noise(s + o_k(cell_k)),  o_k a hash of (cell_k, lattice seed): 10 bits per axis,
//         in [0, 1)^3 periods
//   v = clamp(mu + sum_k w_k (x_k - mu) / sqrt(sum_k w_k^2), 0, 1)   (mu the volume's mean)
//
// The face bands of the four lattices are 2b = 3/16 of a period wide and 1/4 apart, so a
// coordinate lies in at most one lattice's band; three coordinates can silence at most
// three lattices, and sum_k w_k > 0 everywhere (>= 0.003): v is continuous (C1). On
// average 2.15 of the four lattices have weight at a point, and a reader fetches only
// those. The variance-preserving blend keeps the mean and variance of the noise where cells
// overlap (a plain average of independent values would lower their contrast there and thin
// the clouds along the faces), so the coverage thresholds measured on the volume still hold
// (tests/weather_noise_tiling_test.cpp measures both); the clamp keeps the noise's range,
// which the blend leaves only where cells overlap.
// The GPU evaluates the same in shaders/noise_tiling.glsl (identical integer hashes).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "weather/cloud_layer.h"
#include "weather/noise_max_pyramid.h"

namespace cloudsvc::weather {

constexpr int kTilingLattices = 4;
constexpr double kTilingFaceBand = 3.0 / 32.0;  // b: fraction of a period at each face with weight 0

// A layer's tiling seeds for its base and detail noise: from the noise seed and the layer's
// cloud type, so layers of different types do not share a mosaic.
std::uint32_t base_tiling_seed(std::uint32_t noise_seed, CloudType type);
std::uint32_t detail_tiling_seed(std::uint32_t noise_seed, CloudType type);

// The hash seed of lattice k (0..3) of a tiling seed.
std::uint32_t tiling_lattice_seed(std::uint32_t seed, int k);

// The offset o_k of cell c of a lattice with that lattice seed (periods, each axis in
// [0, 1)); exact in float.
glm::dvec3 tiling_offset(const glm::ivec3& cell, std::uint32_t lattice_seed);

// w_k of the header (unnormalised) at x = s - k/4.
double tiling_weight(const glm::dvec3& x);

// The tiled value at s (periods, absolute) of a volume read by `sample` at texture
// coordinates (periods; the volume repeats), for a tiling seed and the volume's mean.
template <class Sampler>
double tiled_noise(const Sampler& sample, const glm::dvec3& s, std::uint32_t seed, double mean) {
  double num = 0.0, w2 = 0.0;
  for (int k = 0; k < kTilingLattices; ++k) {
    const glm::dvec3 sk = s - 0.25 * k;
    const double w = tiling_weight(sk);
    if (w <= 0.0) continue;
    const glm::dvec3 o = tiling_offset(glm::ivec3(glm::floor(sk)), tiling_lattice_seed(seed, k));
    num += w * (sample(s + o) - mean);
    w2 += w * w;
  }
  return std::clamp(mean + num / std::sqrt(w2), 0.0, 1.0);
}

// An upper bound of the tiled noise over the box [lo, hi] (periods, absolute): only the
// lattices with weight somewhere in the box count; one whose weighted part of the box lies
// in one cell reads it at one offset (the pyramid's bound of the shifted box), one whose
// weighted part spans cells may read anything (bound 1).
double tiled_max_over(const NoiseMaxPyramid& pyramid, const glm::dvec3& lo, const glm::dvec3& hi, std::uint32_t seed,
                      double mean);

// The range [min, max] of w_k over the box [x_lo, x_hi] of x = s - k/4 (per axis the bump
// is least at an end of the interval or 0 on a face, largest at the cell centre if it lies
// inside, else at an end; the product of the axes' ranges).
glm::dvec2 tiling_weight_range(const glm::dvec3& x_lo, const glm::dvec3& x_hi);

// The largest blend of taps x_k <= m_k (0 for a lattice without weight) whose weights lie
// in the ranges w_k: with a_k = (m_k - mu)+, sum_k w_k (x_k - mu) / |w| is at most
// sum_k w_k,max a_k / |w_min| and, by Cauchy-Schwarz, |a|; where every m_k <= mu, v <= max_k m_k
// (the weights' gain sum w / |w| >= 1 only pulls v further down).
double tiling_bound(const std::array<double, kTilingLattices>& m, const std::array<glm::dvec2, kTilingLattices>& w,
                    double mean);

}  // namespace cloudsvc::weather
