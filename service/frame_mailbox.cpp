#include "service/frame_mailbox.h"

namespace cloudsvc {

void FrameMailbox::post_pose(PendingPose p) {
  {
    std::lock_guard lock(mutex_);
    ++poses_received_;
    if (pending_.pose) {
      ++poses_dropped_;  // superseded before it was rendered
      // A teleport/reset flag of a dropped pose still applies to the newer one.
      p.pose.flags |= pending_.pose->pose.flags;
    }
    pending_.pose = std::move(p);
  }
  cv_.notify_one();
}

void FrameMailbox::post_change(StateChange c) {
  {
    std::lock_guard lock(mutex_);
    pending_.changes.push_back(std::move(c));
  }
  cv_.notify_one();
}

void FrameMailbox::post_render(PendingRender r) {
  {
    std::lock_guard lock(mutex_);
    pending_.renders.push_back(r);
  }
  cv_.notify_one();
}

void FrameMailbox::request_stop() {
  {
    std::lock_guard lock(mutex_);
    pending_.stop = true;
  }
  cv_.notify_one();
}

MailboxBatch FrameMailbox::take(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  cv_.wait_for(lock, timeout, [&] {
    return pending_.stop || pending_.pose || !pending_.changes.empty() || !pending_.renders.empty();
  });
  MailboxBatch out = std::move(pending_);
  pending_ = MailboxBatch{};
  pending_.stop = out.stop;  // stop is sticky
  return out;
}

std::uint64_t FrameMailbox::poses_received() const {
  std::lock_guard lock(mutex_);
  return poses_received_;
}

std::uint64_t FrameMailbox::poses_dropped() const {
  std::lock_guard lock(mutex_);
  return poses_dropped_;
}

}  // namespace cloudsvc
