// Nested grids ("rings") of the cloud placement (weather/cloud_placement.h) around a centre
// on the shell: what the GPU reads with one bilinear fetch instead of evaluating
// the point process (27 cubes per level, a few hundred hashes) at every density sample.
// As in the nested regular grids of geometry clipmaps (Losasso & Hoppe 2004), ring k has
// texels 2^k times the finest and reaches 2^k times as far. Every ring covers a square of the
// gnomonic plane tangent to the shell at the centre C: a shell point x maps to
//   (u, v) = R (x.e, x.n) / (x.c),  c = C / R, e and n unit tangents at C,
// on which great circles are straight; within 400 km of C its scale departs from the
// shell's by less than 0.5 %. Texel (i, j) of ring k is centred at
//   (u, v) = ((i + 1/2 - N/2) h_k, (j + 1/2 - N/2) h_k),  h_k = h_0 2^k,  N texels a side.
// A texel holds, at the shell point of its centre, a value of the levels the ring draws as
// clouds (those whose smallest radius rho_min s_l spans at least resolve_texels texels; the
// cumulus domes' top, weather::dome_ring_texel_at) and the fraction the smaller levels cover
// (CloudPlacement::covered_below), which a renderer draws as sub-grid cloud.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "weather/cloud_placement.h"

namespace cloudsvc::weather {

struct RingLayout {
  int rings = 6;                // ring 0 .. rings - 1
  int size = 256;               // texels a side, N
  double finest_texel_m = 32.0; // h_0
  double resolve_texels = 3.0;  // a level is drawn where rho_min s_l >= this many texels
};

double ring_texel_m(const RingLayout& layout, int ring);  // h_k (m)
// The first placement level ring `ring` draws (levels below it are folded into the
// covered fraction); params.levels when none is large enough.
int ring_first_level(const RingLayout& layout, const PlacementParams& params, int ring);

// The tangent frame at a centre on the shell (field frame): c = C / |C|; e perpendicular to c
// and the field's z axis (to its x axis where c is that axis, |c.z| > 1 - 1e-12), n = c x e.
struct RingPlane {
  glm::dvec3 c{0.0, 0.0, 1.0}, e{1.0, 0.0, 0.0}, n{0.0, 1.0, 0.0};
  bool operator==(const RingPlane&) const = default;
};
RingPlane ring_plane(const glm::dvec3& centre);

// Plane coordinates (m) of the shell point in direction x (any length; x.c > 0).
glm::dvec2 ring_plane_coords(const RingPlane& plane, double shell_radius_m, const glm::dvec3& x);
// The shell point at plane coordinates uv, relative to the centre C = R c (m, field frame),
// without cancellation: R (w / s - c |w|^2 / (s (1 + s))), w = (u e + v n) / R, s = sqrt(1 + |w|^2).
glm::dvec3 ring_point_from_centre(const RingPlane& plane, double shell_radius_m, const glm::dvec2& uv);
// Plane coordinates of the centre of texel (i, j) of ring `ring`.
glm::dvec2 ring_texel_uv(const RingLayout& layout, int ring, int i, int j);

}  // namespace cloudsvc::weather
