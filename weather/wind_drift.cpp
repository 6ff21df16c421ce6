#include "weather/wind_drift.h"

#include <cmath>

namespace cloudsvc {

glm::dmat3 wind_rotation(const weather::Wind& wind, const WindAnchor& anchor, double unix_time_s) {
  const glm::dvec3 p = geo::geodetic_to_ecef(anchor.position);
  const glm::dvec3 v = geo::enu_to_ecef(anchor.position.lat_deg, anchor.position.lon_deg) *
                       glm::dvec3(wind.east_mps, wind.north_mps, 0.0);
  const double speed = glm::length(v), radius = glm::length(p);
  const glm::dvec3 cross = glm::cross(p, v);
  if (speed <= 0.0 || radius <= 0.0 || glm::length(cross) <= 0.0) return glm::dmat3(1.0);
  const glm::dvec3 k = cross / glm::length(cross);
  // The field rotates by +angle about k; the noise is sampled at the inverse rotation.
  const double angle = std::remainder(speed / radius * (unix_time_s - anchor.unix_time_s), 2.0 * M_PI);
  const double c = std::cos(-angle), s = std::sin(-angle);
  // Rodrigues' formula, column-major: R = c I + s [k]x + (1 - c) k k^T
  const glm::dmat3 K(0.0, k.z, -k.y, -k.z, 0.0, k.x, k.y, -k.x, 0.0);
  return c * glm::dmat3(1.0) + s * K + (1.0 - c) * glm::outerProduct(k, k);
}

}  // namespace cloudsvc
