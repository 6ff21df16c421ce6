// The ground albedo map (weather/ground_albedo_map.h) on the GPU: an RG32F texture of the
// map's grid (R = albedo x weight, G = weight; REPEAT in longitude), created when the map
// first has a texel set and uploaded again whenever its version changes; a 1 x 1 zero
// texture until then. Read by ground_albedo_at (shaders/ground_albedo.glsl). Needs a
// current GL 4.5 context.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "renderer/frame_uniforms_packing.h"
#include "renderer/gl/gl_objects.h"
#include "weather/ground_albedo_map.h"

namespace cloudsvc {

class GroundAlbedoTexture {
 public:
  GroundAlbedoTexture();
  // Uploads the map if it changed since the last call.
  void update(const weather::GroundAlbedoMap& map);
  // Binds the texture at gpu::tex::GROUND_ALBEDO.
  void bind() const;
  // Whether the shaders read the map, and its values at the poles, for the frame uniforms.
  void describe(GpuResourceSummary& resources) const;
  std::size_t gpu_bytes() const { return bytes_; }

 private:
  gl::Texture texture_;
  int width_ = 1, height_ = 1;
  std::uint64_t version_ = 0;
  bool uploaded_ = false;  // version_ is the map's last uploaded version
  bool any_ = false;
  std::array<float, 4> poles_{};  // south (R, G), north (R, G)
  std::size_t bytes_ = 0;
};

}  // namespace cloudsvc
