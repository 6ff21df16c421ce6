// The flight each `sim_client soak` client flies: a steady, coordinated right turn at
// 70 m/s and 3 deg/s (rate one, radius 1337 m, bank 20.5 deg) around a fixed centre near
// Zurich inside the default weather's cloud layers. Every client flies the same circle at
// its own phase (the golden angle, 137.5 deg, apart: never the same for two clients, and
// spread evenly for any number of them) and height (150 m apart, eight heights), so its
// poses are plausible for a simulator (smooth, continuous, moving) and differ from every
// other client's poses: the service's FrameReady echo tells whose pose was rendered.
#pragma once

#include <cstddef>

#include "protocol/messages.h"

namespace cloudsvc::sim {

struct SoakTrack {
  double centre_lat_deg = 47.45;  // circle centre, WGS84
  double centre_lon_deg = 8.56;
  double base_alt_m = 1800.0;     // client 0's height above the ellipsoid
  double alt_step_m = 150.0;      // between clients (client index mod 8)
  double speed_mps = 70.0;        // true airspeed = ground speed (no wind)
  double turn_rate_deg_s = 3.0;   // standard rate, clockwise (right turn)
  double phase_step_deg = 137.50776405003785;  // between clients: 180 (3 - sqrt 5), irrational

  // Client `client`'s pose t_s seconds into the run: sim_time_s = t_s, position on the
  // circle, heading along it, pitch 0, the coordinated-turn bank atan(V w / g),
  // velocity_enu tangent to the circle; no utc_unix_s (the service keeps its clock); no
  // flags.
  protocol::Pose pose(std::size_t client, double t_s) const;
  // Radius of the circle, m: speed / turn rate.
  double radius_m() const;
};

}  // namespace cloudsvc::sim
