// Shared-memory rings per CIGI view (view_rings.h).
#include "service/view_rings.h"

namespace cloudsvc {

ViewRings::ViewRings(std::string base_name, int max_width, int max_height, unsigned mode)
    : base_(std::move(base_name)), max_width_(max_width), max_height_(max_height), mode_(mode) {}

std::string ViewRings::name(std::uint16_t view_id) const { return base_ + "-view" + std::to_string(view_id); }

ShmFrameWriter& ViewRings::ring(std::uint16_t view_id) {
  std::unique_ptr<ShmFrameWriter>& r = rings_[view_id];
  if (!r) r = std::make_unique<ShmFrameWriter>(name(view_id), max_width_, max_height_, mode_);
  return *r;
}

void ViewRings::unlink_names() const {
  for (const auto& [id, r] : rings_)
    if (r) r->unlink_name();
}

}  // namespace cloudsvc
