// Reads frames from the service's shared-memory ring (protocol/shm/shm_layout.h). Lock-free:
// copies a slot between two reads of its seqlock and retries on a concurrent write, so it
// never returns a torn frame and never slows the writer. Every size the ring declares is
// checked against the mapped segment (shm_ring_geometry.h) before any byte is read through
// it, so a corrupt or hostile ring is refused with an error, never read out of bounds.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "protocol/shm/shm_layout.h"
#include "protocol/shm/shm_ring_geometry.h"

namespace cloudsvc {

struct ShmFrame {
  cloudsvc_shm_slot info{};          // slot header copy (frame number, pose echo, size, format)
  std::vector<std::uint8_t> pixels;  // info.height rows of info.row_bytes, top row first
};

class ShmFrameReader {
 public:
  // Maps segment "/name" read-only. Throws std::runtime_error "shared memory /name: ..."
  // (absent, not a cloudsvc ring, unsupported version, or a header whose sizes do not fit
  // the segment: ring_geometry_problem names the field).
  explicit ShmFrameReader(const std::string& name);
  ~ShmFrameReader();
  ShmFrameReader(const ShmFrameReader&) = delete;
  ShmFrameReader& operator=(const ShmFrameReader&) = delete;

  // Copies the newest complete frame whose number is greater than after_frame into out.
  // Returns false when there is none (yet). Retries internally when a slot is being
  // rewritten while it is copied. Throws std::runtime_error "shared memory /name: slot i:
  // ..." when the ring is corrupt: latest_slot outside the ring, or a complete (stable
  // seqlock) slot header whose sizes disagree with the ring (slot_problem names the field).
  bool read_latest(std::uint64_t after_frame, ShmFrame& out);
  // The same for the slot header only (frame number, pose echo, size, format, publish
  // time): no pixel copy, for readers that only follow the ring. Same checks and errors.
  bool read_latest_header(std::uint64_t after_frame, cloudsvc_shm_slot& out);

  // Newest published frame number (0 before the first frame).
  std::uint64_t latest_frame() const;
  // Process id of the writer (0 if unknown).
  std::uint32_t writer_pid() const;

 private:
  // The newest slot's header into info and, when pixels is not null, its pixels (see
  // read_latest).
  bool copy_latest(std::uint64_t after_frame, cloudsvc_shm_slot& info, std::vector<std::uint8_t>* pixels);
  [[noreturn]] void fail_corrupt(const std::string& problem) const;

  std::string path_;          // "/name", for messages
  std::size_t bytes_ = 0;     // size of the mapping (the segment's size at open), bytes
  const std::uint8_t* base_ = nullptr;
  RingGeometry geometry_;     // checked at open; the header's sizes are not re-read
};

}  // namespace cloudsvc
