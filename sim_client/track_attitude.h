// Attitude and velocity derived from a position track alone (IGC logs, ACMI objects
// recorded without orientation).
//
// Method, for each sample i at time t_i:
//  1. Chord: j0 = the earliest sample with t_i - t_j0 <= half_window_s, but at least the
//     previous sample; j1 likewise forward. GeographicLib::Geodesic::WGS84().Inverse from
//     j0 to j1 gives the distance s and the azimuths at both ends; the course is their
//     circular mean. Ground speed V = s / (t_j1 - t_j0), vertical speed w = dh / dt, and
//     velocity_enu = (V sin course, V cos course, w). On a steady turn the symmetric chord
//     is parallel to the tangent at t_i, so this smooths GNSS noise without lagging.
//  2. Heading = course where V >= min_speed_mps; elsewhere (on the ground, hovering) the
//     last valid heading is held (the first valid one before it; 0 if none).
//  3. Pitch = flight-path angle atan2(w, V), clamped to +-max_pitch_deg (ground speed
//     understates airspeed in a headwind, making slow climbs look steep); 0 below
//     min_speed_mps.
//  4. Bank from the coordinated-turn relation tan(phi) = V * omega / g, with the turn rate
//     omega = (heading_{i+1} - heading_{i-1}) / (t_{i+1} - t_{i-1}) (shortest arc) and
//     g = 9.80665 m/s^2; right turns give positive (right-wing-down) roll; |phi| is
//     clamped to max_bank_deg and phi = 0 below min_speed_mps.
// Limits: heading is the track over ground, not where the nose points (differs by the wind
// correction angle, and by sideslip); pitch is the flight path angle, not the attitude
// (differs by the angle of attack, a few degrees, more when slow); bank uses ground
// speed in place of true airspeed (wrong in wind, asymmetric around a thermalling circle)
// and assumes a coordinated turn; sparse fixes (> a few seconds apart) blur fast
// manoeuvres, GNSS jumps show up as spikes.
#pragma once

#include <vector>

#include "sim_client/pose_track.h"

namespace cloudsvc::sim {

struct DerivedAttitudeParams {
  double half_window_s = 2.0;  // chord half-width, s (at least the neighbouring fixes)
  double min_speed_mps = 1.0;  // below: heading held, pitch and bank 0
  double max_pitch_deg = 45.0;  // flight-path angle clamp, deg
  double max_bank_deg = 75.0;   // bank clamp, deg
};

// Fills attitude and velocity_enu_mps of every sample from the positions and times
// (strictly increasing). A single sample gets a zero attitude and no velocity.
void derive_attitude_from_track(std::vector<PoseSample>& samples,
                                const DerivedAttitudeParams& params = {});

}  // namespace cloudsvc::sim
