// Maxima of a tiling noise volume over boxes of texels, for majorants (the path tracer's
// local majorant, renderer/truth/scene_world.h) and conservative empty-space tests (the GPU
// march's long-step probes, as mip levels of a texture, shaders/cloud_density.glsl): level l holds the
// largest texel of every aligned block of 2^l x 2^l x 2^l texels (level 0 is the volume);
// a box of texel indices is covered by at most 2 x 2 x 2 cells of the finest level whose
// cells are at least as large as the box, so a query reads at most 8 values. Indices wrap
// (the volumes tile, GL_REPEAT).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "weather/noise_volumes.h"

namespace cloudsvc::weather {

class NoiseMaxPyramid {
 public:
  NoiseMaxPyramid() = default;
  explicit NoiseMaxPyramid(const NoiseVolume& volume);  // size a power of two

  // Largest value (byte / 255) a trilinear sample can take at texture coordinates u in
  // the box [u_lo, u_hi] (texture units: 1 = one period; any real values, they wrap).
  double max_over(const glm::dvec3& u_lo, const glm::dvec3& u_hi) const;

  int size() const { return size_; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  // Level l: (size >> l)^3 bytes, x fastest.
  const std::vector<std::uint8_t>& level(int l) const { return levels_[static_cast<std::size_t>(l)]; }

 private:
  std::uint8_t cell(int level, int x, int y, int z) const;
  int size_ = 0;
  std::vector<std::vector<std::uint8_t>> levels_;
};

}  // namespace cloudsvc::weather
