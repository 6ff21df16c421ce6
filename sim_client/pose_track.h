// A time-stamped aircraft pose track read from a flight log, with interpolation for
// replay at any time and resampling at a fixed frame rate.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geodesy/geodetic.h"

namespace cloudsvc::sim {

// One pose. Position: WGS84 latitude/longitude (deg) and height above the ellipsoid (m).
// Attitude: aviation convention of geo::Attitude (true heading clockwise from north in
// [0, 360), pitch nose-up positive, roll right-wing-down positive in [-180, 180)).
struct PoseSample {
  double unix_time_s = 0.0;  // UTC, seconds since 1970-01-01T00:00:00Z (leap seconds ignored)
  geo::Geodetic position;
  geo::Attitude attitude;
  // Velocity over ground in the local East-North-Up frame at `position`, m/s, when the log
  // gives or implies it (IGC and ACMI: from the track; CSV: absent).
  std::optional<glm::dvec3> velocity_enu_mps;
};

struct PoseTrack {
  std::string source;               // where the samples came from (file, ACMI object)
  std::vector<PoseSample> samples;  // strictly increasing unix_time_s

  // Pose at a time, interpolated linearly in time between the two neighbouring samples:
  //  - horizontal position along the straight ECEF chord between the two sample points
  //    (taken at zero height) and mapped back to latitude/longitude, so the path takes the
  //    short way across the antimeridian and over or near a pole; the height is
  //    interpolated separately (linear in metres) so long chords do not sag; the longitude
  //    is in [-180, 180) (a point on the antimeridian is -180), the readers' range;
  //  - heading and roll along the shortest arc (heading wrapped to [0, 360), roll to
  //    [-180, 180)), pitch linearly;
  //  - velocity, when both samples have one, in ECEF and expressed in the ENU frame of the
  //    interpolated position.
  // Before the first / after the last sample the end sample is held (its fields returned
  // unchanged except unix_time_s = the requested time). A single-sample track is constant.
  // Throws std::out_of_range on an empty track, std::invalid_argument on a non-finite time.
  // Neighbouring samples are assumed less than half the Earth apart (the chord between
  // antipodes passes through the centre and has no defined direction).
  PoseSample at(double unix_time_s) const;

  double start_time() const { return samples.front().unix_time_s; }
  double end_time() const { return samples.back().unix_time_s; }
};

// Frames for replay at `fps` frames per second: times t0 + k / fps for k = 0, 1, ... while
// <= the last sample time (t0 = first sample time; times computed from k, not summed, so
// they do not drift). The last sample is included only when the span is a whole number of
// frames (within 1e-9 frame). An empty track gives no frames. max_frames > 0 keeps only the
// first max_frames of them, and only those are computed and held (a long log replayed at a
// high rate with --max-frames costs what the frames asked for, not the whole log). Throws
// std::invalid_argument when fps is not finite and positive or the frames returned would
// exceed 50 million.
std::vector<PoseSample> resample(const PoseTrack& track, double fps, std::size_t max_frames = 0);

}  // namespace cloudsvc::sim
