#include "weather/placement_rings.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace cloudsvc::weather {

double ring_texel_m(const RingLayout& layout, int ring) { return std::ldexp(layout.finest_texel_m, ring); }

int ring_first_level(const RingLayout& layout, const PlacementParams& params, int ring) {
  const double need = layout.resolve_texels * ring_texel_m(layout, ring);
  for (int l = 0; l < params.levels; ++l)
    if (params.rho_min * std::ldexp(params.smallest_cell_m, l) >= need) return l;
  return params.levels;
}

RingPlane ring_plane(const glm::dvec3& centre) {
  RingPlane p;
  p.c = glm::normalize(centre);
  const glm::dvec3 axis = std::abs(p.c.z) > 1.0 - 1e-12 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
  p.e = glm::normalize(glm::cross(axis, p.c));
  p.n = glm::cross(p.c, p.e);
  return p;
}

glm::dvec2 ring_plane_coords(const RingPlane& plane, double shell_radius_m, const glm::dvec3& x) {
  const double k = shell_radius_m / glm::dot(x, plane.c);
  return {k * glm::dot(x, plane.e), k * glm::dot(x, plane.n)};
}

glm::dvec3 ring_point_from_centre(const RingPlane& plane, double shell_radius_m, const glm::dvec2& uv) {
  const glm::dvec3 w = (uv.x * plane.e + uv.y * plane.n) / shell_radius_m;
  const double w2 = glm::dot(w, w), s = std::sqrt(1.0 + w2);
  return shell_radius_m * (w / s - plane.c * (w2 / (s * (1.0 + s))));
}

glm::dvec2 ring_texel_uv(const RingLayout& layout, int ring, int i, int j) {
  const double h = ring_texel_m(layout, ring), half = 0.5 * layout.size;
  return {(i + 0.5 - half) * h, (j + 0.5 - half) * h};
}

}  // namespace cloudsvc::weather
