#include "service/sim_clock.h"

namespace cloudsvc {

void SimClock::set(double utc_s) {
  base_utc_s_ = utc_s;
  base_sim_s_.reset();
}

double SimClock::utc_for(const protocol::Pose& p) const {
  if (p.utc_unix_s) return *p.utc_unix_s;
  return base_utc_s_ + (base_sim_s_ ? p.sim_time_s - *base_sim_s_ : 0.0);
}

void SimClock::observe(const protocol::Pose& p) {
  if (p.utc_unix_s) {
    base_utc_s_ = *p.utc_unix_s;
    base_sim_s_ = p.sim_time_s;
  } else if (!base_sim_s_) {
    base_sim_s_ = p.sim_time_s;
  }
}

}  // namespace cloudsvc
