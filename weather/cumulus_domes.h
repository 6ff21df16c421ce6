// Cumulus as individual clouds (issue 15): the layer is the union of parabolic domes standing
// on a flat base, one per cloud of a weather::CloudPlacement, with outlines roughened by a
// domain warp. This file holds what the GPU and the CPU reference share: the placement's
// parameters per layer, its seed, the warp and the dome top at a shell point.
//
// Shape of one cloud of radius r (m) at horizontal distance d from its centre: over the
// parabolic footprint u = (r^2 - d^2) / r (r at the centre, 0 on the rim) the top is
//   top = min(sqrt(u L), ceiling)   (m above the layer base; L = kDomeTopScale_m)
// a dome with vertical sides at the rim, as cumulus have, sqrt(r L) tall: 320 m for a cloud
// of 100 m radius, 1.4 km for one of 2 km (larger cumulus are taller, smaller ones
// relatively taller still), capped by the layer's ceiling (the type channel's f_v times the
// layer depth, weather/cloud_layer.h): the larger clouds of a shallow layer (humilis, under
// an inversion) spread flat under it. The union's height field is the max over clouds (the
// max of u: the top is monotonic in it).
//
// Sizes: cells of 500 m to 4 km (four levels), radii 0.2-0.5 of the cell (100 m to 2 km).
// Cumulus fields follow power laws N(>A) ∝ A^(-b) (Cahalan & Joseph 1989); this model
// takes b = 1.1 - 0.4 c with c the layer's coverage, so that a broken field holds larger
// clouds than a scattered one, not only more of them.
//
// Outlines: the point x looks up the placement at x + w(x), w a five-octave gradient-noise
// displacement (wavelengths 8 km / 2^o down to 500 m, amplitude 1500 m (lambda / 8 km)^0.3,
// i.e. about the wavelength's size at 500 m): the discs' smooth rims become outlines of
// perimeter-area dimension near the 1.35 of satellite and radar cloud fields (Lovejoy 1982);
// tests/reference_cumulus_domes_test.cpp measures it (weaker warps give 1.2-1.3: rims stay
// smooth at the scale of the many small clouds).
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "weather/cloud_layer.h"
#include "weather/cloud_placement.h"
#include "weather/placement_rings.h"

namespace cloudsvc::weather {

// The sphere the placement lives on (field frame, m): one for every layer, so that a layer's
// clouds stand at the same place whatever its altitude (points are projected radially).
inline constexpr double kDomeShellRadius_m = 6371000.0;
inline constexpr double kDomeSmallestCell_m = 500.0;  // the smallest clouds: 100 m radius
inline constexpr int kDomeLevels = 4;  // cells 500 m .. 4 km

// The cloud inside a dome (shaders/cloud_density.glsl and the CPU reference evaluate it):
// at height h above the base under the top T = min(sqrt(unit top L), ceiling), with the
// layer's base-shape noise S (its median subtracted) raising and lowering the top by up to
// kDomeCauliflower_m where the dome is at least that tall (cauliflower tops; a flat base),
// the cloud fraction is
//   d = saturate((T + A saturate(T / A) 2 (S - S_median) - h) / edge) * saturate(h / base_ramp)
// (crisp convective edges: tens of metres).
inline constexpr double kDomeTopScale_m = 1000.0;  // L
inline constexpr double kDomeCauliflower_m = 150.0;
inline constexpr double kDomeEdge_m = 60.0;
inline constexpr double kDomeBaseRamp_m = 40.0;
double dome_fraction(double unit_top_m, double ceiling_m, double h_m, double shape_minus_median);

// The domain warp of the outlines (see above).
inline constexpr int kDomeWarpOctaves = 5;
inline constexpr double kDomeWarpLongest_m = 8000.0;  // octave o: wavelength 8 km / 2^o
inline constexpr double kDomeWarpAmplitude_m = 1500.0; // at 8 km; times (lambda / 8 km)^0.3
inline constexpr double kDomeWarpAmplitudeSlope = 0.3;

// Cumulus layers are drawn as domes; every other type keeps the noise-threshold field.
bool uses_domes(CloudType t);

// The placement of a layer with coverage c (the layer's own value, before the map).
PlacementParams dome_placement_params(double layer_coverage);

// The radius of the largest cloud the placement can hold (m): rho_max times the largest cell.
double dome_largest_radius_m();

// The placement seed of layer `index` of w: from the map seed, the layer's type and its
// ordinal among the layers of that type, so that adding or removing another layer leaves a
// layer's clouds where they were.
std::uint32_t dome_placement_seed(const Weather& w, std::size_t index);

// The warp's displacement at the shell point x (field frame, m), as the shell point it
// moves x to: x + w(x) projected onto the shell of x's radius. octaves: how many of the
// octaves, longest first (a grid of texel h draws those of wavelength >= 3.5 h:
// dome_warp_octaves).
class DomeWarp {
 public:
  explicit DomeWarp(std::uint32_t seed);
  glm::dvec3 warped(const glm::dvec3& x, int octaves = kDomeWarpOctaves) const;
  // |w| can never exceed this (m): sqrt(3) times the noise's bound times the summed amplitudes.
  static double max_displacement_m();

  struct Octave {
    double wavelength_m, amplitude_m;
    std::uint32_t seed[3];  // one noise per axis
  };
  const Octave& octave(int o) const { return octave_[o]; }

 private:
  Octave octave_[kDomeWarpOctaves];
};

// The warp octaves a grid of texel texel_m draws: those of wavelength >= 3.5 texels (finer
// ones would alias).
int dome_warp_octaves(double texel_m);

// The unit-aspect dome top (m) of placement cp over levels [first, end) at the shell point x
// (before the warp; the warp's first `octaves` octaves are applied here), never below
// -floor_m: the footprint height u a renderer turns into the cloud's top (dome_fraction;
// CloudPlacement::dome_top).
double dome_top_unit_aspect(const CloudPlacement& cp, const DomeWarp& warp, const glm::dvec3& x,
                            const CloudPlacement::CoverageAt& coverage, int first, int end, double floor_m,
                            int octaves = kDomeWarpOctaves);

// The clouds of the levels a grid cannot draw (those below ring_first_level of the finest
// ring covering a point), drawn as sub-grid cloud: a gradient-noise field n with two octaves
// per such level l, of wavelengths s_l and 0.41 s_l (s_l the level's cell), weights 1 and
// 0.5, each on its own rotated lattice (so that no lattice axis or period shows); cloud
// where n exceeds its quantile at
// 1 - covered (the fraction those levels cover, CloudPlacement::covered_below), so the
// sub-grid clouds cover what the placement's would, with blobs of their levels' sizes.
// The unit-aspect top there is (n - q) / |n|_rms times the mean radius of the finest
// level (dome_subgrid_top_m): a blob's height grows from its rim like a dome's.
inline constexpr int kDomeSubgridQuantiles = 64;  // quantile table entries, 0..1 in equal steps
// The sub-grid top's scale: the mean radius of the finest level, (rho_min + rho_max) / 2 of its cell.
inline constexpr double kDomeSubgridMeanRadius_m = 0.35 * kDomeSmallestCell_m;
class DomeSubgrid {
 public:
  explicit DomeSubgrid(std::uint32_t seed);
  // n over the first `levels` levels (1..kDomeLevels) at the shell point x (field frame)
  double noise(const glm::dvec3& x, int levels) const;
  // the value below which a fraction p of n(levels) lies (table over 65 536 shell points)
  double quantile(double p, int levels) const;
  // |n(levels)|_rms
  double rms(int levels) const { return rms_[levels]; }
  // the unit-aspect sub-grid top (m) at x where the first `levels` levels cover `covered`;
  // negative outside the blobs, -floor_m at most
  double top_m(const glm::dvec3& x, int levels, double covered, double floor_m) const;

  // octaves 2l and 2l + 1 belong to level l
  static constexpr int kOctaves = 2 * kDomeLevels;
  struct Octave {
    double wavelength_m, weight;
    glm::dmat3 rotation;  // field axes -> the octave's lattice axes
    std::uint32_t seed;
  };
  const Octave& octave(int i) const { return octave_[i]; }
  const double* quantile_table(int levels) const { return quantiles_[levels]; }

 private:
  Octave octave_[kOctaves];
  double quantiles_[kDomeLevels + 1][kDomeSubgridQuantiles + 1] = {};
  double rms_[kDomeLevels + 1] = {};
};

// The rings a renderer reads a dome layer's tops from (weather/placement_rings.h): four
// rings of 256^2 texels of 64 m to 512 m around the camera's nadir, reaching 8 to 64 km;
// ring k draws the levels whose smallest radius is at least one of its texels (ring 0 all
// four, ring 3 the largest only: ring_first_level), with every warp octave it can resolve,
// and the finer levels are sub-grid cloud there. A point reads the finest ring holding it.
RingLayout dome_ring_layout();

// The texel of ring `ring` centred at plane coordinates uv (m) of the plane tangent to the
// shell at `centre` (field frame, m; weather/dome_rings.h places the rings): the unit-aspect
// top of the levels the ring draws (from ring_first_level up) at the texel's shell point with
// the warp octaves its texel draws, never below -4 texels (dome_ring_floor_m), and the
// fraction of the shell the finer levels cover at the layer's coverage there
// (CloudPlacement::covered_below), which a renderer draws as sub-grid cloud.
struct DomeRingTexel {
  double top_m = 0.0;
  double covered_below = 0.0;
};
DomeRingTexel dome_ring_texel_at(const CloudPlacement& cp, const DomeWarp& warp, const RingLayout& layout,
                                 const RingPlane& plane, const glm::dvec3& centre, int ring, const glm::dvec2& uv,
                                 const CloudPlacement::CoverageAt& coverage);
double dome_ring_floor_m(const RingLayout& layout, int ring);

}  // namespace cloudsvc::weather
