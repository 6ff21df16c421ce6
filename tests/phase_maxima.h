// Angles of maxima of sampled curves, and of a phase table's rings around the antisolar
// point (renderer/model/mie_phase_table.h): how tests find the glory's first ring and the
// fogbow.
#pragma once

#include <cmath>

#include "renderer/model/mie_phase_table.h"

namespace cloudsvc::test {

// The position of the largest of f(0..n-1) over [lo, hi] (indices), refined by the parabola
// through it and its neighbours; -1 if the largest sits on the range's edge (no maximum inside).
template <typename F>
double parabolic_maximum(F f, int lo, int hi) {
  int best = lo;
  for (int k = lo; k <= hi; ++k)
    if (f(k) > f(best)) best = k;
  if (best == lo || best == hi) return -1.0;
  const double a = f(best - 1), b = f(best), c = f(best + 1);
  const double den = a - 2.0 * b + c;
  return best + (den < 0.0 ? 0.5 * (a - c) / den : 0.0);
}

// Angle from the antisolar point (deg) of the phase table's maximum of channel c within
// [from_deg, to_deg], sampled every step_deg (angle from the antisolar point =
// 180 deg - scattering angle).
inline double table_maximum_deg(const model::PhaseTable& t, int c, double from_deg, double to_deg, double step_deg = 0.01) {
  const int lo = static_cast<int>(std::lround(from_deg / step_deg)), hi = static_cast<int>(std::lround(to_deg / step_deg));
  const double k = parabolic_maximum([&](int i) { return t.at_angle_deg(180.0 - i * step_deg)[c]; }, lo, hi);
  return k < 0.0 ? -1.0 : k * step_deg;
}

// Angle from the antisolar point (deg) of the glory's first ring in channel c of the table:
// walking out from the antisolar point over the table's samples, the first maximum after
// the central peak's first minimum (refined by a parabola); -1 if there is none within 10 deg.
inline double glory_first_ring_deg(const model::PhaseTable& t, int c) {
  const auto p = [&](int k) { return t.phase[static_cast<std::size_t>(model::kPhaseTableSamples - 1 - k)][c]; };
  const double step = model::phase_table_angle_deg(model::kPhaseTableSamples - 1) -
                      model::phase_table_angle_deg(model::kPhaseTableSamples - 2);
  const int last = static_cast<int>(10.0 / step);
  int k = 1;
  while (k < last && !(p(k) < p(k - 1) && p(k) <= p(k + 1))) ++k;  // the first minimum
  while (k < last && !(p(k) > p(k - 1) && p(k) >= p(k + 1))) ++k;  // the next maximum
  if (k >= last) return -1.0;
  return parabolic_maximum(p, k - 1, k + 1) * step;
}

}  // namespace cloudsvc::test
