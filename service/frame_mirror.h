// Mirrored views (CIGI View Definition's mirror mode, docs/CIGI.md): a view drawn as usual,
// then flipped as a mirror or a rear-projection screen shows it.
#pragma once

#include <cstdint>

#include "renderer/api/frame_image.h"

namespace cloudsvc {

// CIGI 3.3 View Definition mirror mode: horizontal flips left and right (about the image's
// vertical centre line), vertical flips top and bottom, both does both (a half turn).
enum class MirrorMode : std::uint8_t { None = 0, Horizontal = 1, Vertical = 2, Both = 3 };

// The image flipped in place as `mode` says: its pixels and, where present, their standard
// errors; its statistics are the image's and stay.
void mirror_image(FrameImage& img, MirrorMode mode);

}  // namespace cloudsvc
