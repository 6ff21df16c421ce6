// Wind advection of the cloud field on the sphere. A layer's wind (east, north, m/s) is
// a solid-body rotation of its cloud field about an axis through the Earth's centre,
// chosen so that at the anchor point P the field moves with exactly that wind:
//   axis = normalise(P x v),  angular speed w = |v| / |P|.
// Unlike "offset = wind * t along the camera's east/north", this is one motion for the
// whole globe: it does not change when the camera moves (no swimming clouds), is
// continuous at the poles, and its angle w (t - t0) is wrapped modulo 2 pi, so a service
// that runs for weeks keeps full precision.
#pragma once

#include <glm/glm.hpp>

#include "geodesy/geodetic.h"
#include "weather/cloud_layer.h"

namespace cloudsvc {

// Where and when the cloud field is at its reference position. The renderer latches the
// first view after a weather change (so a single render shows the field undisplaced and
// a sequence shows it drifting from there).
struct WindAnchor {
  geo::Geodetic position;
  double unix_time_s = 0.0;
};

// Rotation that takes a world (ECEF) position at time t to where the cloud now there was
// at the anchor time: the noise is sampled at rotation * x.
glm::dmat3 wind_rotation(const weather::Wind& wind, const WindAnchor& anchor, double unix_time_s);

}  // namespace cloudsvc
