// The simulation clock of `cloudsvc serve` (service/render_loop.h): the UTC of each pose.
#pragma once

#include <optional>

#include "protocol/messages.h"

namespace cloudsvc {

// UTC of each pose: its own when it carries one, else the last SetTime (or the command
// line's --time) advanced by the simulation time since then.
class SimClock {
 public:
  void set(double utc_s);
  // The pose's effective UTC, without changing the clock.
  double utc_for(const protocol::Pose& p) const;
  // Takes the pose as the clock's new reference (after it was found valid).
  void observe(const protocol::Pose& p);
  double base_utc_s() const { return base_utc_s_; }

 private:
  double base_utc_s_ = 0.0;
  std::optional<double> base_sim_s_;  // sim time of the first pose after the base was set
};

}  // namespace cloudsvc
