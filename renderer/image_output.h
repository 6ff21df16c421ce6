// Writing frames to files with OpenImageIO: EXR = linear radiance as 32-bit float RGBA
// (A = cloud opacity), plus se.R, se.G, se.B (the standard error of R, G, B) when the
// frame carries one (FrameImage::std_error: the path-traced truth); PNG = tone-mapped 8-bit sRGB for people (common/tone_map.h, which
// also gives luminance()). The image is encoded in
// memory, written to a fresh temporary of unpredictable name created exclusively in the
// same folder, and renamed into place: a failed write leaves no partial file, and a file or
// symbolic link someone planted under the temporary's or the final name is never written
// through.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/tone_map.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc {

// Writes img to path; the format follows the extension (.exr or .png, case-insensitive).
// PNG: tone_map_srgb8 (common/tone_map.h) with exposure_ev, stops. Throws
// std::runtime_error naming the path on failure.
void write_image(const std::string& path, const FrameImage& img, double exposure_ev = 0.0);

}  // namespace cloudsvc
