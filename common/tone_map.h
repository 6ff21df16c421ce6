// Display tone mapping of the service's linear radiance frames: the one recipe behind the
// service's PNG frames, its RGBA8 shared-memory frames and window, and sim_client's
// conversion of EXR frames (sweep --png, contact sheets). GL-free.
//
// Input: linear radiance, W m^-2 sr^-1 nm^-1 at 680/550/440 nm, treated as linear Rec.709
// R, G, B. The recipe:
//   1. auto exposure: key 0.18 over the log-average luminance (Reinhard et al. 2002,
//      "Photographic Tone Reproduction for Digital Images", eq. 1) of the pixels whose
//      luminance is finite and below 10 W m^-2 sr^-1 nm^-1 (the sun disk and glints are
//      ignored; a negative luminance counts as 0); the factor clamped to [0.5, 5000] so
//      that night stays dark; times 2^exposure_ev;
//   2. per channel: exposure x radiance through the ACES filmic fit of Narkowicz 2015
//      ("ACES Filmic Tone Mapping Curve"), then the sRGB transfer function (IEC
//      61966-2-1), giving a display value in [0, 1].
// A non-finite (NaN, +-Inf) or negative channel becomes 0 (black): no NaN reaches a pixel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace cloudsvc {

// Luminance of a radiance triple (R, G, B = 680/550/440 nm) with the Rec.709 weights.
inline double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

// The tone curve of one frame: its exposure factor, and the display value of a channel.
struct ToneMap {
  double exposure = 1.0;  // factor on radiance (sr nm m^2 W^-1) before the ACES curve

  // Display value in [0, 1] (sRGB-encoded) of one linear channel; 0 for NaN, +-Inf and
  // negative values.
  double display(float radiance) const;
};

// The tone curve of `pixels`: interleaved, `channels` values per pixel (>= 3; R, G, B
// first, any further channel such as alpha ignored), step 1 of the recipe above.
ToneMap tone_map_for(std::span<const float> pixels, int channels, double exposure_ev = 0.0);

// RGBA8 sRGB of `pixels` (as for tone_map_for): 4 bytes per pixel, R, G, B rounded to the
// nearest of 0..255, alpha 255.
std::vector<std::uint8_t> tone_map_srgb8(std::span<const float> pixels, int channels, double exposure_ev = 0.0);

// Display values in [0, 1] of `pixels` (as for tone_map_for), same layout: R, G, B tone
// mapped, every further channel (alpha) 1.
std::vector<float> tone_map_display(std::span<const float> pixels, int channels, double exposure_ev = 0.0);

}  // namespace cloudsvc
