// Where a cumulus layer's dome rings (weather/cumulus_domes.h, dome_ring_layout) lie for a
// camera, and the dome top a renderer reads from them: what the GPU samples
// (shaders/cumulus_domes.glsl) and the CPU reference evaluates the same way, in double.
//
// Placement of the rings, a pure function of the camera's position (so that the reference
// finds the same rings without the renderer's history):
//  - one gnomonic plane for all rings (weather/placement_rings.h), tangent to the dome shell
//    at the anchor A: the centre of the 64 km cube of the field frame holding the camera's
//    nadir, projected onto the shell (it moves only when the nadir leaves that cube; the
//    plane's scale departs from the shell's by < 0.05 % within 100 km of A);
//  - ring k centred at the nadir's plane coordinates rounded to a multiple of N/8 texels of
//    the ring (it scrolls in steps of 1/8 of its width; the nadir stays within 1/16 of its
//    width of the centre), so its texel centres lie on one grid of the plane,
//    (m + 1/2) h_k, whatever the centre: a texel's value depends on A, k and m only.
// Reading the top at a shell point x: the finest ring k whose bilinear footprint holds x
// gives rep_k(x) = max(the bilinear top of ring k, the sub-grid top of the levels below
// ring_first_level(k) with ring k's covered fraction); beyond the last ring every level is
// sub-grid. Over the outer eighth of ring k's half-width rep_k blends linearly into
// rep_{k+1}, so no seam shows where the level of detail changes.
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "weather/cumulus_domes.h"

namespace cloudsvc::weather {

inline constexpr double kDomeAnchorCell_m = 64000.0;
inline constexpr int kDomeMaxRings = 4;

struct DomeRings {
  glm::dvec3 anchor{0.0};  // A, on the dome shell (field frame, m)
  RingPlane plane;         // tangent at A
  std::array<glm::dvec2, kDomeMaxRings> origin{};  // plane coordinates of each ring's centre (m)
  bool operator==(const DomeRings& o) const = default;
};

// The rings of `layout` (at most kDomeMaxRings) for a camera at camera_field (field frame,
// m, any radius).
DomeRings dome_rings_for(const RingLayout& layout, const glm::dvec3& camera_field);

// The weight of ring k's own representation at plane coordinates uv: 1 inside, falling
// linearly to 0 over the outer eighth of its half-width (in texels from its centre, less the
// bilinear footprint's 1.5 texels), 0 outside.
double dome_ring_weight(const RingLayout& layout, const DomeRings& rings, int ring, const glm::dvec2& uv);

}  // namespace cloudsvc::weather

namespace cloudsvc::weather {

// The CPU's reading of a dome layer's top (the GPU's, in double): texel values are computed
// on first use (dome_ring_texel at the texel's plane coordinates) and kept, keyed by anchor,
// ring and texel; safe to call from several threads.
class DomeTopSampler {
 public:
  DomeTopSampler(const CloudPlacement& cp, const DomeWarp& warp, const DomeSubgrid& subgrid, const RingLayout& layout,
                 CloudPlacement::CoverageAt coverage);
  ~DomeTopSampler();
  DomeTopSampler(const DomeTopSampler&) = delete;
  DomeTopSampler& operator=(const DomeTopSampler&) = delete;

  // The unit-aspect top (m) at the shell point x (field frame) with the rings `rings`;
  // coverage_here: the layer's coverage at x (the sub-grid's beyond the last ring).
  double top_m(const DomeRings& rings, const glm::dvec3& x, double coverage_here) const;

  // Ring k's bilinear top and covered fraction at plane coordinates uv (inside the ring).
  DomeRingTexel ring_bilinear(const DomeRings& rings, int ring, const glm::dvec2& uv) const;

 private:
  DomeRingTexel texel(const DomeRings& rings, int ring, long long mi, long long mj) const;
  const CloudPlacement& cp_;
  const DomeWarp& warp_;
  const DomeSubgrid& subgrid_;
  RingLayout layout_;
  CloudPlacement::CoverageAt coverage_;
  struct Cache;
  Cache* cache_;
};

}  // namespace cloudsvc::weather
