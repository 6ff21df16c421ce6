// A camera flying a level turn, as a sequence of views: the temporal-reuse benchmark of
// issue 5 ("a camera flying at 250 m/s at 30 frames/s through and past clouds, and
// turning at 3 deg/s"). Positions integrate the velocity along the current heading in the
// local East-North-Up frame of the previous position (double precision, GeographicLib
// through geodesy/), so the track is exact to well under a millimetre per frame.
#pragma once

#include <cmath>
#include <vector>

#include "geodesy/geodetic.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc::bench {

struct FlightSequence {
  ViewRequest start;           // first view (position, attitude, time, size, fov)
  double speed_mps = 250.0;    // true airspeed along the heading, level
  double turn_rate_dps = 3.0;  // heading change, degrees per second (positive: right)
  double fps = 30.0;
  int frames = 30;
};

inline std::vector<ViewRequest> flight_views(const FlightSequence& s) {
  std::vector<ViewRequest> out;
  ViewRequest v = s.start;
  const double dt = 1.0 / s.fps;
  for (int i = 0; i < s.frames; ++i) {
    v.frame_index = s.start.frame_index + static_cast<std::uint32_t>(i);
    v.reset_history = i == 0 && s.start.reset_history;
    out.push_back(v);
    // advance: straight segment along the mid-step heading, in the local ENU frame
    const double mid_heading = (v.attitude.heading_deg + 0.5 * s.turn_rate_dps * dt) * M_PI / 180.0;
    const glm::dvec3 step_enu(std::sin(mid_heading) * s.speed_mps * dt, std::cos(mid_heading) * s.speed_mps * dt, 0.0);
    const glm::dvec3 ecef = geo::geodetic_to_ecef(v.position) +
                            geo::enu_to_ecef(v.position.lat_deg, v.position.lon_deg) * step_enu;
    const double alt = v.position.alt_m;
    v.position = geo::ecef_to_geodetic(ecef);
    v.position.alt_m = alt;  // level flight: hold the altitude above the ellipsoid
    v.attitude.heading_deg = std::fmod(v.attitude.heading_deg + s.turn_rate_dps * dt + 360.0, 360.0);
    v.unix_time_s += dt;
  }
  return out;
}

}  // namespace cloudsvc::bench
