// Where a CIGI view's eye is and where it looks (cigi_ig_state.h): the ownship's pose moved
// by the view's offset in the ownship's body axes (x forward, y right, z down, m) and turned
// by the view's rotation relative to the ownship (yaw, then pitch, then roll, degrees, as an
// aircraft attitude is to the local level frame).
#pragma once

#include "geodesy/geodetic.h"
#include "protocol/cigi/cigi_ig_state.h"

namespace cloudsvc::cigi {

struct ViewPose {
  geo::Geodetic position;  // height above the ellipsoid (the ownship's altitude as given)
  geo::Attitude attitude;  // of the view in its own local level frame
};

ViewPose view_pose(const OwnshipPose& ownship, const View& view);

}  // namespace cloudsvc::cigi
