// The shared-memory rings of the CIGI views (`serve --cigi --shm NAME`): view ID's frames go
// to ring NAME-view<ID>, made when the view is first drawn, with the --shm ring's size limit
// and permissions. Used by the render thread while it holds the publish mutex; the network
// thread takes the mutex before it removes the names on an abandoned shutdown.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "protocol/shm/shm_frame_writer.h"

namespace cloudsvc {

class ViewRings {
 public:
  ViewRings(std::string base_name, int max_width, int max_height, unsigned mode);

  // "NAME-view<ID>".
  std::string name(std::uint16_t view_id) const;
  // View id's ring, made on first use; throws std::runtime_error when it cannot be made (the
  // name belongs to another live cloudsvc, no memory), and again on every later call.
  ShmFrameWriter& ring(std::uint16_t view_id);
  // Removes every ring's name now (a process about to exit without destructors).
  void unlink_names() const;

 private:
  std::string base_;
  int max_width_, max_height_;
  unsigned mode_;
  std::map<std::uint16_t, std::unique_ptr<ShmFrameWriter>> rings_;
};

}  // namespace cloudsvc
