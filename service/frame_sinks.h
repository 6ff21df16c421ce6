// The sink steps of a frame in `cloudsvc serve`: RenderLoop calls them, for the sinks the
// view asks for, while it holds the publish mutex (service/render_loop.h).
#pragma once

#include <cstdint>
#include <string>

#include "geodesy/geodetic.h"
#include "protocol/messages.h"
#include "renderer/api/frame_image.h"
#include "protocol/shm/shm_frame_writer.h"

namespace cloudsvc {

// The slot header of a frame rendered for `pose` at `utc_s`.
ShmFrameMeta shm_frame_meta(std::uint64_t frame, const protocol::Pose& pose, double utc_s, const FrameImage& img);
// ... for an eye at `position` with `attitude` (a CIGI view), at sim time `sim_time_s`.
ShmFrameMeta shm_frame_meta(std::uint64_t frame, double sim_time_s, double utc_s, const geo::Geodetic& position,
                            const geo::Attitude& attitude, const FrameImage& img);

// Encodes the frame in `format` (RGBA16F linear or RGBA8 sRGB) and writes it to the next
// slot of the ring; returns the slot. Throws what ShmFrameWriter::write throws.
std::uint32_t publish_to_shm(ShmFrameWriter& shm, const FrameImage& img, const ShmFrameMeta& meta,
                             protocol::ShmPixelFormat format);

// Writes frame_<frame, 6 digits>.png or .exr (view.file_format) into view.file_dir, which is
// checked against `root` (the canonical --out-dir) again for every frame: a directory
// accepted earlier may since have been replaced by a link leading out of --out-dir.
// Returns the path written; throws std::exception with the reason when the directory is
// refused or the image cannot be written.
std::string publish_to_file(const FrameImage& img, std::uint64_t frame, const protocol::SetView& view,
                            const std::string& root);

}  // namespace cloudsvc
