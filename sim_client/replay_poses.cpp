// Replay poses from a track (replay_poses.h).
#include "sim_client/replay_poses.h"

#include "geodesy/utc_time.h"
#include "protocol/validate.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

std::vector<protocol::Pose> replay_poses(const PoseTrack& track, double fps, std::size_t max_frames) {
  const std::vector<PoseSample> samples = resample(track, fps, max_frames);  // only the frames sent
  std::vector<protocol::Pose> poses;
  poses.reserve(samples.size());
  const double t0 = track.start_time();
  for (const PoseSample& s : samples) {
    protocol::Pose p;
    p.sim_time_s = s.unix_time_s - t0;
    p.utc_unix_s = s.unix_time_s;
    p.lat_deg = s.position.lat_deg;
    p.lon_deg = s.position.lon_deg;
    p.alt_m = s.position.alt_m;
    p.heading_deg = s.attitude.heading_deg;
    p.pitch_deg = s.attitude.pitch_deg;
    p.roll_deg = s.attitude.roll_deg;
    if (s.velocity_enu_mps) p.velocity_enu = protocol::VelocityEnu{s.velocity_enu_mps->x, s.velocity_enu_mps->y, s.velocity_enu_mps->z};
    if (poses.empty()) p.flags = protocol::pose_flag::kTeleport;
    if (auto problem = protocol::validate(protocol::Message(p)))
      throw UsageError(track.source + ": pose at " + geo::format_utc_iso8601(s.unix_time_s) + ": " + *problem);
    poses.push_back(p);
  }
  return poses;
}

}  // namespace cloudsvc::sim
