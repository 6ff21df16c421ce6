#include "service/frame_mailbox.h"

#include <set>
#include <utility>

namespace cloudsvc {

FrameMailbox::FrameMailbox(std::size_t tile_budget_bytes) : tile_budget_bytes_(tile_budget_bytes) {}

std::size_t FrameMailbox::tile_bytes(const protocol::WeatherMapTile& tile) { return tile.data.size() * sizeof(float); }

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

bool FrameMailbox::post_change(StateChange c) {
  {
    std::lock_guard lock(mutex_);
    if (const auto* tile = std::get_if<protocol::WeatherMapTile>(&c)) {
      const std::size_t bytes = tile_bytes(*tile);
      if (tile_bytes_ + bytes > tile_budget_bytes_) return false;
      tile_bytes_ += bytes;
    }
    pending_.changes.push_back(std::move(c));
  }
  cv_.notify_one();
  return true;
}

bool FrameMailbox::post_render(PendingRender r) {
  {
    std::lock_guard lock(mutex_);
    std::size_t& n = renders_by_client_[r.client_id];
    if (n >= kMaxRendersPerClient) return false;
    ++n;
    pending_.renders.push_back(r);
  }
  cv_.notify_one();
  return true;
}

void FrameMailbox::render_finished(std::uint64_t client_id) {
  std::lock_guard lock(mutex_);
  auto it = renders_by_client_.find(client_id);
  if (it != renders_by_client_.end() && --it->second == 0) renders_by_client_.erase(it);
}

void FrameMailbox::tile_applied(const protocol::WeatherMapTile& tile) {
  std::lock_guard lock(mutex_);
  const std::size_t bytes = tile_bytes(tile);
  tile_bytes_ = bytes <= tile_bytes_ ? tile_bytes_ - bytes : 0;
}

bool FrameMailbox::post_cigi(cigi::HostDatagram d) {
  {
    std::lock_guard lock(mutex_);
    if (pending_.cigi.size() >= kMaxCigiDatagrams) {
      ++pending_.cigi_refused;
      return false;
    }
    pending_.cigi.push_back(std::move(d));
  }
  cv_.notify_one();
  return true;
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
    return pending_.stop || pending_.pose || !pending_.changes.empty() || !pending_.renders.empty() ||
           !pending_.cigi.empty() || pending_.cigi_refused > 0;
  });
  MailboxBatch out;
  out.pose = std::move(pending_.pose);
  pending_.pose.reset();
  out.changes = std::move(pending_.changes);
  pending_.changes.clear();
  out.cigi = std::move(pending_.cigi);
  pending_.cigi.clear();
  out.cigi_refused = std::exchange(pending_.cigi_refused, 0);
  out.stop = pending_.stop;  // stop is sticky: it stays pending
  // The oldest request of each client; the others wait for the next batch.
  std::set<std::uint64_t> taken;
  std::vector<PendingRender> later;
  for (const PendingRender& r : pending_.renders) {
    if (taken.insert(r.client_id).second) out.renders.push_back(r);
    else later.push_back(r);
  }
  pending_.renders = std::move(later);
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
