// Where individual clouds stand on the cloud shell (issue 15), between the weather map's
// scale (texels of tens of km, which give the covered fraction) and the shape noise's
// (hundreds of metres, which gives each cloud its form).
//
// A multi-level marked point process in the field frame (ECEF turned with the wind, m):
// level k tiles space with cubes of edge s_k = smallest_cell_m * 2^k, each holding one
// candidate point placed uniformly in it by a hash of the cube's integer index and the seed.
// The candidates within s_k / 2 of the shell sphere (radius R) are projected onto it. A slab
// of thickness s_k holds area * s_k / s_k^3 cube points whatever its orientation, so their
// density on the shell is 1 / s_k^2 everywhere: no seam at the poles or the antimeridian
// and no lattice direction. A candidate is a cloud with probability p_k (another hash) and
// has the radius rho * s_k, rho uniform in [rho_min, rho_max] (a disc stays inside the
// 3 x 3 x 3 cubes around the point it covers).
//
// Sizes: level k adds p_k / s_k^2 clouds of area ~ s_k^2 per unit area; p_k ∝ s_k^(2 - 2b)
// makes the number of clouds larger than A fall as N(>A) ∝ A^(-b) over the levels' range
// (power laws of cumulus sizes: Cahalan & Joseph 1989; b is a genus parameter).
// Coverage: level k's discs cover a_k = p_k pi <rho^2> of the shell; levels are
// independent, so the covered fraction is 1 - prod(1 - a_k). The p_k are scaled so that it
// equals the weather map's coverage read at the candidate's own centre (a cloud exists or
// not as a whole, whatever point looks at it).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

namespace cloudsvc::weather {

struct PlacementParams {
  double smallest_cell_m = 500.0;  // s_0
  int levels = 6;                  // s_0 .. s_0 * 2^(levels - 1)
  double size_exponent = 1.0;      // b of N(>A) ∝ A^(-b)
  double rho_min = 0.2, rho_max = 0.5;
};

struct PlacedCloud {
  glm::dvec3 centre{0.0};  // on the shell, field frame (m)
  double radius_m = 0.0;
  int level = 0;
  std::uint32_t id = 0;  // hash of level and cube: per-cloud noise offsets, shapes
};

class CloudPlacement {
 public:
  // Throws std::invalid_argument for a non-positive cell, levels outside 1..16, a size
  // exponent outside (0, 3) or rho outside 0 < rho_min <= rho_max <= 0.5.
  CloudPlacement(const PlacementParams& params, double shell_radius_m, std::uint32_t seed);

  // The acceptance probability p_k of each level for covered fraction c in [0, 1]; the
  // largest c reachable with every p_k = 1 is max_coverage().
  std::vector<double> acceptance(double coverage) const;
  double max_coverage() const;

  // Coverage of the weather map at a point of the shell (field frame, m), in [0, 1].
  using CoverageAt = std::function<double(const glm::dvec3&)>;

  // The clouds of levels first_level.. whose disc (great-circle distances taken as chords)
  // contains the shell point x, appended to out.
  void clouds_at(const glm::dvec3& x, const CoverageAt& coverage, std::vector<PlacedCloud>& out,
                 int first_level = 0) const;

  // max over those clouds of 1 - (d / r)^2 (0 where none): a cloud's footprint, 1 at its
  // centre, falling to 0 at its rim.
  double envelope(const glm::dvec3& x, const CoverageAt& coverage, int first_level = 0) const;

  // The parabolic dome of unit aspect over the clouds of levels [first_level, end_level)
  // near the shell point x: max over their accepted candidates of (r^2 - d^2) / r (m;
  // r at the centre, 0 on the rim, negative outside), and never below -floor_m. Every
  // candidate within one cube of x is visited, so a cloud it misses gives less than -3 r
  // of its level: exact wherever the result is above -3 rho_min s_first.
  // (weather/cumulus_domes.h scales it by the layer's aspect.)
  double dome_top(const glm::dvec3& x, const CoverageAt& coverage, int first_level, int end_level,
                  double floor_m) const;

  // The expected fraction of the shell that the levels below first_level cover at coverage
  // c, 1 - exp(-sum_k p_k(c) pi <rho^2>) (the Poisson form acceptance() solves): what a
  // grid too coarse to draw those clouds keeps of them (weather/placement_rings.h).
  double covered_below(int first_level, double coverage) const;

  const PlacementParams& params() const { return params_; }
  double shell_radius_m() const { return R_; }
  std::uint32_t level_seed(int level) const;  // the hash seed of a level's cubes

  // p_k at coverage c as the placement reads it (tabulated, linear interpolation)
  double level_acceptance(int level, double coverage) const;
  // The table it interpolates: row i (coverage i / kCoverageSteps) holds p_k of each level.
  static constexpr int kCoverageSteps = 1024;
  const std::vector<double>& acceptance_table() const { return acceptance_table_; }

 private:
  PlacementParams params_;
  double R_;
  std::uint32_t seed_;
  double mean_rho2_;
  // Calls f(level, centre, radius, hash) for every cloud of levels [first, end) whose cube
  // is within one cube of x's on its level (the candidates that may cover x) for which
  // want(centre, radius) holds and which the coverage at its centre accepts (asked last).
  template <class Want, class F>
  void for_each_nearby_cloud(const glm::dvec3& x, const CoverageAt& coverage, int first, int end, Want&& want,
                             F&& f) const;
  std::vector<double> level_weight_;  // (s_k / s_0)^(2 - 2b), normalised to max 1
  std::vector<double> acceptance_table_;  // acceptance_table()
};

}  // namespace cloudsvc::weather
