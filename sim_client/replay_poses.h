// The protocol poses of a replay: a flight-log track resampled at a frame rate.
#pragma once

#include <cstddef>
#include <vector>

#include "protocol/messages.h"
#include "sim_client/pose_track.h"

namespace cloudsvc::sim {

// resample(track, fps), at most max_frames of them (0 = all), as Poses:
// sim_time_s = seconds since the first sample, utc_unix_s = the sample's UTC, position and
// attitude as sampled, velocity_enu when the log gives one; the first pose has the
// teleport flag (no temporal history from whatever the service showed before). Every pose
// is checked with protocol::validate (the service's ranges are narrower than the logs':
// altitude [-500, 100000] m). Throws UsageError
// "<track.source>: pose at 2026-06-21T12:00:05Z: Pose.alt_m -600 out of range [-500, 100000]"
// and std::invalid_argument for a bad fps (pose_track.h).
std::vector<protocol::Pose> replay_poses(const PoseTrack& track, double fps, std::size_t max_frames);

}  // namespace cloudsvc::sim
