// What to draw: the camera pose, time and image size of one frame. Plain data shared by
// the GPU renderer and the CPU reference (no GL).
#pragma once

#include <cstdint>

#include "geodesy/geodetic.h"

namespace cloudsvc {

// One view: where the camera is, where it looks, when, and the image size.
struct ViewRequest {
  geo::Geodetic position;      // WGS84, altitude above the ellipsoid (m)
  geo::Attitude attitude;      // heading/pitch/roll, degrees
  double unix_time_s = 0.0;    // UTC, seconds since 1970-01-01
  double fov_deg = 60.0;       // horizontal field of view
  int width = 640;
  int height = 360;
  std::uint32_t frame_index = 0;  // varies the per-pixel jitter and the temporally marched pixels
  bool reset_history = false;     // a teleport or sim reset: reuse nothing from earlier frames
};

}  // namespace cloudsvc
