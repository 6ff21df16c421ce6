// Where a straight ray crosses a sphere concentric with the shell, as both roots of
//   t^2 + 2 (R + h) mu t + c = 0,   c = (h - H)(2R + h + H)
// for a ray starting at altitude h above the sphere of radius R with zenith cosine mu,
// and a sphere at altitude H (the cancellation-free form of Haines et al. 2019,
// Ray Tracing Gems ch. 7, as in geo::intersect_shell: q = b' + sign(b') sqrt(b'^2 - c), roots c / q and q with
// b' = -(R + h) mu). Unlike geo::intersect_shell, roots behind the start are kept, which
// is what interval logic needs (inside the sphere for t0 < t < t1).
#pragma once

#include <cmath>
#include <optional>
#include <utility>

namespace cloudsvc::reference {

struct SphereCrossings {
  double t0 = 0.0, t1 = 0.0;  // t0 <= t1, metres along the ray (negative: behind the start)
};

inline std::optional<SphereCrossings> sphere_crossings(double R, double h, double H, double mu) {
  const double c = (h - H) * (2.0 * R + h + H);
  const double b = -(R + h) * mu;
  const double disc = b * b - c;
  if (!(disc >= 0.0)) return std::nullopt;
  const double q = b + (b >= 0.0 ? std::sqrt(disc) : -std::sqrt(disc));
  SphereCrossings s;
  if (q == 0.0) return s;  // start on the sphere, horizontal: double root at 0
  s.t0 = c / q;
  s.t1 = q;
  if (s.t0 > s.t1) std::swap(s.t0, s.t1);
  return s;
}

}  // namespace cloudsvc::reference
