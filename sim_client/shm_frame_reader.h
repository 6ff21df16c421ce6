// Reads frames from the service's shared-memory ring (protocol/shm_layout.h). Lock-free:
// copies a slot between two reads of its seqlock and retries on a concurrent write, so it
// never returns a torn frame and never slows the writer.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "protocol/shm_layout.h"

namespace cloudsvc::client {

struct ShmFrame {
  cloudsvc_shm_slot info{};          // slot header copy (frame number, pose echo, size, format)
  std::vector<std::uint8_t> pixels;  // info.height rows of info.row_bytes, top row first
};

class ShmFrameReader {
 public:
  // Maps segment "/name" read-only. Throws std::runtime_error (absent, not a cloudsvc
  // ring, unsupported version).
  explicit ShmFrameReader(const std::string& name);
  ~ShmFrameReader();
  ShmFrameReader(const ShmFrameReader&) = delete;
  ShmFrameReader& operator=(const ShmFrameReader&) = delete;

  // Copies the newest complete frame whose number is greater than after_frame into out.
  // Returns false when there is none (yet). Retries internally when a slot is being
  // rewritten while it is copied.
  bool read_latest(std::uint64_t after_frame, ShmFrame& out);
  // The same for the slot header only (frame number, pose echo, size, format, publish
  // time): no pixel copy, for readers that only follow the ring.
  bool read_latest_header(std::uint64_t after_frame, cloudsvc_shm_slot& out);

  // Newest published frame number (0 before the first frame).
  std::uint64_t latest_frame() const;
  // Process id of the writer (0 if unknown).
  std::uint32_t writer_pid() const;

 private:
  std::size_t bytes_ = 0;
  const std::uint8_t* base_ = nullptr;
};

}  // namespace cloudsvc::client
