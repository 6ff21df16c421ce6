// A contact sheet: one PNG mosaic of up to 16 evenly spaced frames of a replay, each
// labelled with its frame number, for a quick look at a whole flight.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cloudsvc::sim {

inline constexpr std::size_t kContactSheetMaxFrames = 16;
inline constexpr int kContactSheetMaxTileWidth = 400;  // px; wider frames are scaled down
inline constexpr int kContactSheetGap = 4;             // px between tiles

// Up to n indices into [0, count) evenly spaced, first and last included (all of them when
// count <= n), ascending and distinct.
std::vector<std::size_t> pick_evenly(std::size_t count, std::size_t n);

struct SheetFrame {
  std::string path;               // image written by the service (PNG or EXR)
  std::uint64_t frame_number = 0;
};

// Writes the mosaic as an 8-bit sRGB PNG: ceil(sqrt(k)) columns of tiles the size of the
// first frame (scaled to at most kContactSheetMaxTileWidth wide), on a dark background,
// each labelled with its frame number when a font is available (drawing text is skipped
// otherwise). EXR frames are tone mapped (tone_map.h). Throws std::runtime_error naming the
// file that cannot be read or written; std::invalid_argument for no frames.
void write_contact_sheet(const std::vector<SheetFrame>& frames, const std::string& out_path);

}  // namespace cloudsvc::sim
