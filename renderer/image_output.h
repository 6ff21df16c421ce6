// Writing frames to files with OpenImageIO: EXR = linear radiance as half float RGBA
// (A = cloud opacity); PNG = tone-mapped 8-bit sRGB for people. The image is encoded in
// memory, written to a fresh temporary of unpredictable name created exclusively in the
// same folder, and renamed into place: a failed write leaves no partial file, and a file or
// symbolic link someone planted under the temporary's or the final name is never written
// through.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc {

// Tone mapping for display: auto exposure from the log-average luminance (key 0.18,
// clamped so that night stays dark), an EV offset, the ACES filmic fit of Narkowicz 2015,
// and the sRGB transfer function. Returns width*height*4 bytes, alpha 255.
std::vector<std::uint8_t> tone_map_srgb8(const FrameImage& img, double exposure_ev = 0.0);

// Writes img to path; the format follows the extension (.exr or .png, case-insensitive).
// Throws std::runtime_error naming the path on failure.
void write_image(const std::string& path, const FrameImage& img, double exposure_ev = 0.0);

// Luminance of the 680/550/440 nm radiance triple, treated as linear Rec.709 primaries.
inline double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

}  // namespace cloudsvc
