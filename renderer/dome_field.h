// The cumulus layers' dome fields on the GPU (weather/cumulus_domes.h): per layer that uses
// domes, its placement, warp and sub-grid (made when the layer or the weather changes), its
// four rings placed for the camera (weather/dome_rings.h) and filled when they move or the
// weather map changes, and the per-layer data shaders/cumulus_domes.glsl reads
// (renderer/dome_layer_gpu.h). Layer i uses ring slot i. Needs a current GL 4.5 context.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "renderer/dome_layer_gpu.h"
#include "renderer/frame_context.h"
#include "renderer/frame_uniforms.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/placement_rings.h"
#include "weather/cloud_layer.h"

namespace cloudsvc {

class DomeField {
 public:
  DomeField();

  // Brings the rings and the per-layer data up to date for frame `frame` of `weather`
  // (frame.layers[i].domes marks the layers drawn as domes); weather_generation changes
  // whenever the weather maps the GPU sees change. The weather map textures must be bound
  // (CloudFieldTextures::bind): the ring fill reads the map at each cloud's centre.
  // Returns the number of rings filled.
  int update(const FrameContext& frame, const weather::Weather& weather, std::uint64_t weather_generation,
             const FrameUniforms& uniforms);

  // Binds the rings (gpu::tex::DOME_RINGS) and the per-layer data (gpu::ssbo::DOME_LAYERS).
  void bind() const;

 private:
  struct Layer {
    std::uint32_t seed = 0;
    double coverage = -1.0;
    std::unique_ptr<weather::CloudPlacement> placement;
    std::unique_ptr<weather::DomeWarp> warp;
    std::unique_ptr<weather::DomeSubgrid> subgrid;
    std::optional<weather::DomeRings> filled;  // the rings as last filled
    std::uint64_t filled_generation = 0;
  };
  weather::RingLayout layout_;
  PlacementRings rings_;
  std::array<Layer, gpu::kMaxLayers> layers_;
  std::array<DomeLayerGpu, gpu::kMaxLayers> gpu_{};
  gl::Buffer buffer_;
};

}  // namespace cloudsvc
