// Ray / spherical-shell intersection in a cancellation-free form (Haines et al. 2019,
// "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7; the
// float error figures are in docs/SOURCES.md and docs/STABILITY.md). The ray starts at altitude h above a sphere of radius R (the ground),
// with mu = cos(angle between the ray and the local up at the start); the shell is the
// sphere of radius R + H. Only the altitudes and mu are needed, never Earth-centred
// coordinates, so float evaluation stays accurate to millimetres (see tests).
//
//   c  = (h - H)(2R + h + H)        = |O|^2 - (R+H)^2, exact-ish for small h - H
//   b' = -(R + h) mu                 (half linear coefficient, sign flipped)
//   q  = b' + sign(b') sqrt(b'^2 - c)
//   roots t = c / q and t = q
#pragma once

#include <cmath>

namespace cloudsvc::geo {

template <class T>
struct ShellHits {
  int count = 0;  // number of hits with t >= 0 (0, 1 or 2)
  T t_near = 0;   // first hit distance (valid if count >= 1), m
  T t_far = 0;    // second hit distance (valid if count == 2), m
};

// Distances along the ray to the sphere of radius R + H, from a start at altitude h.
// Hits behind the start (t < 0) are dropped. A tangent ray counts as two equal hits.
// The roots are those of t^2 - 2 b' t + c = 0, i.e. |O + t D|^2 = (R + H)^2 with
// |O| = R + h, O.D = (R + h) mu; their product is c, so c / q is the second root.
// Cases (reviewed and tested in tests/geodesy_shell_test.cpp):
//   below the shell (h < H, c < 0): one hit, t_near > 0, for every mu;
//   above (h > H, c > 0): two hits when looking down steeply enough, else none;
//   exactly on it (h == H, c == 0): a root at t = 0. Looking down (mu < 0) gives
//     count 2 {0, -2(R+h)mu}; looking up (mu > 0) gives count 1 {0}; mu == 0 is the
//     tangent double root, count 2 {0, 0}.
// NaN input gives count 0 (no NaN reaches a caller that trusts count).
template <class T>
ShellHits<T> intersect_shell(T R, T h, T H, T mu) {
  ShellHits<T> out;
  const T c = (h - H) * (T(2) * R + h + H);
  const T b = -(R + h) * mu;
  const T disc = b * b - c;
  if (!(disc >= T(0))) return out;  // miss, or NaN input
  const T s = std::sqrt(disc);
  const T q = b + (b >= T(0) ? s : -s);
  T t0, t1;
  if (q == T(0)) {  // only when b == 0 and c == 0: ray starts on the shell, horizontal
    t0 = t1 = T(0);
  } else {
    t0 = c / q;
    t1 = q;
  }
  if (t0 > t1) { T tmp = t0; t0 = t1; t1 = tmp; }
  if (t1 < T(0)) return out;
  if (t0 < T(0)) {
    out.count = 1;
    out.t_near = t1;
    return out;
  }
  out.count = 2;
  out.t_near = t0;
  out.t_far = t1;
  return out;
}

}  // namespace cloudsvc::geo
