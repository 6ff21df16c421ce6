#include "weather/cumulus_domes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "weather/gradient_noise.h"
#include "weather/noise_hash.h"

namespace cloudsvc::weather {

namespace {
// Stream numbers of detail::sub_seed (arbitrary, distinct).
constexpr std::uint32_t kPlacementStream = 0x646f6d65u;  // "dome"
constexpr std::uint32_t kWarpStream = 0x77617270u;       // "warp"
constexpr std::uint32_t kSubgridStream = 0x73756267u;    // "subg"
// Each sub-grid level is two octaves on their own rotated lattices, of wavelengths A and B
// times the level's cell (incommensurate, so the lattices' regularity does not show) and
// weights 1 and weight_b. Chosen so that the blobs have the size of the level's clouds
// (tests/reference_cumulus_domes_test.cpp).
constexpr double kSubgridWavelengthA = 1.0, kSubgridWavelengthB = 0.41, kSubgridWeightB = 0.7;
// |perlin_noise| stays below this (the improved noise's bound is about 1.04).
constexpr double kPerlinBound = 1.1;
}  // namespace

double dome_fraction(double unit_top_m, double ceiling_m, double h_m, double shape_minus_median) {
  const double A = kDomeCauliflower_m;
  const double T = std::min(std::sqrt(std::max(unit_top_m, 0.0) * kDomeTopScale_m), ceiling_m);
  const double top = T + A * std::clamp(T / A, 0.0, 1.0) * 2.0 * shape_minus_median;
  return std::clamp((top - h_m) / kDomeEdge_m, 0.0, 1.0) * std::clamp(h_m / kDomeBaseRamp_m, 0.0, 1.0);
}

bool uses_domes(CloudType t) { return t == CloudType::Cumulus; }

PlacementParams dome_placement_params(double layer_coverage) {
  PlacementParams p;
  p.smallest_cell_m = kDomeSmallestCell_m;
  p.levels = kDomeLevels;
  p.size_exponent = 1.1 - 0.4 * std::clamp(layer_coverage, 0.0, 1.0);
  return p;
}

double dome_largest_radius_m() {
  const PlacementParams p = dome_placement_params(0.0);
  return p.rho_max * std::ldexp(p.smallest_cell_m, p.levels - 1);
}

std::uint32_t dome_placement_seed(const Weather& w, std::size_t index) {
  const CloudType type = w.layers.at(index).type;
  std::uint32_t ordinal = 0;
  for (std::size_t i = 0; i < index; ++i) ordinal += w.layers[i].type == type ? 1u : 0u;
  const std::uint32_t s = detail::sub_seed(w.map_seed, kPlacementStream);
  return detail::sub_seed(detail::sub_seed(s, static_cast<std::uint32_t>(type)), ordinal);
}

DomeWarp::DomeWarp(std::uint32_t seed) {
  const std::uint32_t s = detail::sub_seed(seed, kWarpStream);
  for (int o = 0; o < kDomeWarpOctaves; ++o) {
    Octave& oc = octave_[o];
    oc.wavelength_m = std::ldexp(kDomeWarpLongest_m, -o);
    oc.amplitude_m = kDomeWarpAmplitude_m * std::pow(oc.wavelength_m / kDomeWarpLongest_m, kDomeWarpAmplitudeSlope);
    for (std::uint32_t a = 0; a < 3; ++a) oc.seed[a] = detail::sub_seed(s, 3u * static_cast<std::uint32_t>(o) + a);
  }
}

double DomeWarp::max_displacement_m() {
  double sum = 0.0;
  for (int o = 0; o < kDomeWarpOctaves; ++o)
    sum += kDomeWarpAmplitude_m * std::pow(std::ldexp(1.0, -o), kDomeWarpAmplitudeSlope);
  return std::sqrt(3.0) * kPerlinBound * sum;
}

int dome_warp_octaves(double texel_m) {
  int n = 0;
  while (n < kDomeWarpOctaves && std::ldexp(kDomeWarpLongest_m, -n) >= 3.5 * texel_m) ++n;
  return n;
}

glm::dvec3 DomeWarp::warped(const glm::dvec3& x, int octaves) const {
  glm::dvec3 w(0.0);
  for (int o = 0; o < std::min(octaves, kDomeWarpOctaves); ++o) {
    const Octave& oc = octave_[o];
    const glm::dvec3 u = x / oc.wavelength_m;
    for (int a = 0; a < 3; ++a) w[a] += oc.amplitude_m * detail::perlin_noise(u.x, u.y, u.z, 0, oc.seed[a]);
  }
  const glm::dvec3 y = x + w;
  return y * (glm::length(x) / glm::length(y));
}

double dome_top_unit_aspect(const CloudPlacement& cp, const DomeWarp& warp, const glm::dvec3& x,
                            const CloudPlacement::CoverageAt& coverage, int first, int end, double floor_m,
                            int octaves) {
  return cp.dome_top(warp.warped(x, octaves), coverage, first, end, floor_m);
}

DomeSubgrid::DomeSubgrid(std::uint32_t seed) {
  const std::uint32_t s = detail::sub_seed(seed, kSubgridStream);
  for (int i = 0; i < kOctaves; ++i) {
    Octave& oc = octave_[i];
    const int level = i / 2;
    oc.wavelength_m = std::ldexp(kDomeSmallestCell_m, level) * (i % 2 == 0 ? kSubgridWavelengthA : kSubgridWavelengthB);
    oc.weight = i % 2 == 0 ? 1.0 : kSubgridWeightB;
    oc.seed = detail::sub_seed(s, static_cast<std::uint32_t>(i));
    // a rotation from three hashed angles (z-x-z Euler angles)
    const double a = 2.0 * std::numbers::pi * detail::hash_to_unit(detail::hash32(oc.seed ^ 0x1u));
    const double b = std::acos(1.0 - 2.0 * detail::hash_to_unit(detail::hash32(oc.seed ^ 0x2u)));
    const double c = 2.0 * std::numbers::pi * detail::hash_to_unit(detail::hash32(oc.seed ^ 0x3u));
    const auto rz = [](double t) {
      return glm::dmat3(std::cos(t), std::sin(t), 0.0, -std::sin(t), std::cos(t), 0.0, 0.0, 0.0, 1.0);
    };
    const glm::dmat3 rx(1.0, 0.0, 0.0, 0.0, std::cos(b), std::sin(b), 0.0, -std::sin(b), std::cos(b));
    oc.rotation = rz(a) * rx * rz(c);
  }
  // quantiles of n over a fixed set of shell points (a Fibonacci lattice on the shell; the
  // noise is stationary, so any large set gives the same table)
  constexpr int kPoints = 65536;
  std::vector<double> v(kPoints);
  for (int levels = 1; levels <= kDomeLevels; ++levels) {
    double sum2 = 0.0;
    for (int i = 0; i < kPoints; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / kPoints, r = std::sqrt(1.0 - z * z);
      const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
      v[i] = noise(kDomeShellRadius_m * glm::dvec3(r * std::cos(phi), r * std::sin(phi), z), levels);
      sum2 += v[i] * v[i];
    }
    std::sort(v.begin(), v.end());
    rms_[levels] = std::sqrt(sum2 / kPoints);
    for (int q = 0; q <= kDomeSubgridQuantiles; ++q)
      quantiles_[levels][q] = v[std::min<std::size_t>(kPoints - 1, static_cast<std::size_t>(
                                                                      static_cast<double>(q) / kDomeSubgridQuantiles * kPoints))];
  }
}

double DomeSubgrid::noise(const glm::dvec3& x, int levels) const {
  double n = 0.0;
  for (int i = 0; i < 2 * std::min(levels, kDomeLevels); ++i) {
    const glm::dvec3 u = octave_[i].rotation * x / octave_[i].wavelength_m;
    n += octave_[i].weight * detail::perlin_noise(u.x, u.y, u.z, 0, octave_[i].seed);
  }
  return n;
}

double DomeSubgrid::quantile(double p, int levels) const {
  const double x = std::clamp(p, 0.0, 1.0) * kDomeSubgridQuantiles;
  const int i = std::min(static_cast<int>(x), kDomeSubgridQuantiles - 1);
  return quantiles_[levels][i] + (x - i) * (quantiles_[levels][i + 1] - quantiles_[levels][i]);
}

double DomeSubgrid::top_m(const glm::dvec3& x, int levels, double covered, double floor_m) const {
  if (levels <= 0 || covered <= 0.0) return -floor_m;
  const double t = kDomeSubgridMeanRadius_m * (noise(x, levels) - quantile(1.0 - covered, levels)) / rms_[levels];
  return std::max(t, -floor_m);
}

RingLayout dome_ring_layout() {
  RingLayout l;
  l.rings = 4;
  l.size = 256;
  l.finest_texel_m = 64.0;
  l.resolve_texels = 1.0;
  return l;
}

double dome_ring_floor_m(const RingLayout& layout, int ring) { return 4.0 * ring_texel_m(layout, ring); }

DomeRingTexel dome_ring_texel_at(const CloudPlacement& cp, const DomeWarp& warp, const RingLayout& layout,
                                 const RingPlane& plane, const glm::dvec3& centre, int ring, const glm::dvec2& uv,
                                 const CloudPlacement::CoverageAt& coverage) {
  const glm::dvec3 x = centre + ring_point_from_centre(plane, cp.shell_radius_m(), uv);
  const int first = ring_first_level(layout, cp.params(), ring), end = cp.params().levels;
  DomeRingTexel t;
  t.top_m = dome_top_unit_aspect(cp, warp, x, coverage, first, end, dome_ring_floor_m(layout, ring),
                                 dome_warp_octaves(ring_texel_m(layout, ring)));
  t.covered_below = cp.covered_below(first, coverage(x));
  return t;
}

}  // namespace cloudsvc::weather
