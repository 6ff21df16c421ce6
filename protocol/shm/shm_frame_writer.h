// Writes rendered frames into the POSIX shared-memory ring described in
// protocol/shm/shm_layout.h (seqlocked slots, round-robin, never blocks on readers).
#pragma once

#include <cstdint>
#include <string>

#include "protocol/shm/shm_layout.h"

namespace cloudsvc {

struct ShmFrameMeta {
  std::uint64_t frame_number = 0;
  double sim_time_s = 0.0, unix_time_s = 0.0;
  double lat_deg = 0.0, lon_deg = 0.0, alt_m = 0.0;
  double heading_deg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;
  double render_ms = 0.0;
};

class ShmFrameWriter {
 public:
  // Creates (or takes over a stale) segment "/name" (name: shm_name.h) able to hold frames up to
  // max_width x max_height in either pixel format, with permissions `mode` (exactly:
  // created owner-only, then set). Throws std::runtime_error if the name is invalid, the
  // segment belongs to another live cloudsvc, or memory cannot be had.
  ShmFrameWriter(const std::string& name, int max_width, int max_height, unsigned mode = 0600, int slot_count = 3);
  ~ShmFrameWriter();  // unmaps and removes the segment

  // Removes the name now (readers that have it mapped keep the last whole frame); for a
  // process about to exit without running destructors.
  void unlink_name() const;
  ShmFrameWriter(const ShmFrameWriter&) = delete;
  ShmFrameWriter& operator=(const ShmFrameWriter&) = delete;

  // Copies one frame (rows top first, row_bytes each) into the next slot and publishes it.
  // Returns the slot index. Frames larger than the segment's maximum throw.
  std::uint32_t write(const ShmFrameMeta& meta, std::uint32_t pixel_format, int width, int height,
                      const void* pixels, std::size_t row_bytes);

  const std::string& name() const { return name_; }
  int max_width() const { return max_width_; }
  int max_height() const { return max_height_; }

 private:
  std::string name_;
  int max_width_, max_height_;
  std::uint32_t slot_count_;
  std::size_t bytes_ = 0;
  std::uint8_t* base_ = nullptr;
  std::uint32_t next_slot_ = 0;
};

}  // namespace cloudsvc
