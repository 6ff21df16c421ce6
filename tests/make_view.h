// A ViewRequest from its parts, for tests (GL-free: the reference and truth tests use it
// as well as the image tests, tests/render_test_support.h).
#pragma once

#include <string>

#include "geodesy/utc_time.h"
#include "renderer/api/view_request.h"

namespace cloudsvc::test {

// Camera at (lat, lon, alt m), heading and pitch in degrees (no roll), at an ISO 8601 UTC
// time, w x h pixels, horizontal field of view fov degrees.
inline ViewRequest make_view(double lat, double lon, double alt, double heading, double pitch,
                             const std::string& time_utc, int w = 160, int h = 90, double fov = 60.0) {
  ViewRequest v;
  v.position = {lat, lon, alt};
  v.attitude = {heading, pitch, 0.0};
  v.unix_time_s = *geo::parse_utc_iso8601(time_utc);
  v.width = w;
  v.height = h;
  v.fov_deg = fov;
  return v;
}

}  // namespace cloudsvc::test
