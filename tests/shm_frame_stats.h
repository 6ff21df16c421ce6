// Statistics of a frame read back from the service's shared-memory ring, for tests that
// compare service-rendered frames: mean luminance and cloud fraction of an RGBA16F frame.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "protocol/shm/shm_frame_reader.h"

namespace cloudsvc::test {

// IEEE 754 binary16 -> float (exact, including subnormals, Inf and NaN).
inline float half_to_float(std::uint16_t h) {
  const std::uint32_t sign = (h >> 15) & 1u, exp = (h >> 10) & 0x1fu, mant = h & 0x3ffu;
  float v;
  if (exp == 0) v = std::ldexp(static_cast<float>(mant), -24);
  else if (exp == 31) v = mant ? NAN : INFINITY;
  else v = std::ldexp(static_cast<float>(mant | 0x400u), static_cast<int>(exp) - 25);
  return sign ? -v : v;
}

struct FrameStats {
  double mean_luminance = 0.0;  // mean Y = 0.2126 R + 0.7152 G + 0.0722 B, W m^-2 sr^-1 nm^-1
  double cloud_fraction = 0.0;  // fraction of pixels with alpha (cloud opacity) > 0.01
  std::size_t nonfinite = 0;    // pixels with a NaN/Inf channel
};

// Statistics of an RGBA16F linear frame (pixel_format CLOUDSVC_SHM_RGBA16F_LINEAR).
inline FrameStats stats_of(const ShmFrame& f) {
  FrameStats s;
  const std::size_t n = static_cast<std::size_t>(f.info.width) * f.info.height;
  if (n == 0 || f.info.pixel_format != CLOUDSVC_SHM_RGBA16F_LINEAR) return s;
  std::size_t cloudy = 0, finite = 0;
  double sum = 0.0;
  for (std::uint32_t y = 0; y < f.info.height; ++y) {
    for (std::uint32_t x = 0; x < f.info.width; ++x) {
      std::uint16_t px[4];
      std::memcpy(px, f.pixels.data() + static_cast<std::size_t>(y) * f.info.row_bytes + x * 8u, 8);
      const float r = half_to_float(px[0]), g = half_to_float(px[1]), b = half_to_float(px[2]), a = half_to_float(px[3]);
      if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b) || !std::isfinite(a)) {
        ++s.nonfinite;
        continue;
      }
      ++finite;
      sum += 0.2126 * r + 0.7152 * g + 0.0722 * b;
      if (a > 0.01f) ++cloudy;
    }
  }
  s.mean_luminance = finite ? sum / static_cast<double>(finite) : 0.0;
  s.cloud_fraction = static_cast<double>(cloudy) / static_cast<double>(n);
  return s;
}

// Reads frame `frame_number` from ring `shm` (the newest frame must be that one, as it is
// right after its FrameReady when one client drives the service). False if it is not.
inline bool read_frame(const std::string& shm, std::uint64_t frame_number, ShmFrame& out) {
  ShmFrameReader reader(shm);
  return reader.read_latest(frame_number - 1, out) && out.info.frame_number == frame_number;
}

}  // namespace cloudsvc::test
