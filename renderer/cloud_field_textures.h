// The cloud field on the GPU: the base-shape and detail noise volumes (and the base's max
// pyramid, weather/noise_max_pyramid.h), the two weather-map
// keyframes around the frame time (weather/weather_timeline.h) and their coverage
// max-pyramid (renderer/coverage_pyramid.h), with what the frame uniforms say about them
// (GpuResourceSummary). Every pass that evaluates the cloud density binds them with bind().
// Needs a current GL 4.5 context.
#pragma once

#include <string>
#include <vector>
#include <cstddef>
#include <cstdint>

#include "renderer/frame_uniforms_packing.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/model/mie_phase_table.h"
#include "weather/weather_timeline.h"

namespace cloudsvc {

struct RendererConfig {
  int base_noise_size = 128;   // Perlin-Worley base shape volume edge
  int detail_noise_size = 32;  // Worley detail volume edge
  std::uint32_t noise_seed = 1;
  int weather_map_width = 1024;  // global map, 0.35 deg per texel
  int weather_map_height = 512;
  // Cumulus layers as individual domes over the cloud placement (weather/cumulus_domes.h,
  // renderer/dome_field.h) instead of the thresholded noise field. Off by default until
  // their shader path is cheap enough on llvmpipe and the default preset's accuracy on them
  // is at its floors (docs/MORPHOLOGY.md, "Domes in the renderer and the reference").
  bool cumulus_domes = false;
  // Both noise volumes read through their stochastic tiling (weather/noise_tiling.h), so
  // the cloud field does not repeat with the noise's period. Off by default until it is
  // cheap enough on llvmpipe: the march costs 1.4-1.7x (docs/MORPHOLOGY.md, "Noise tiling").
  bool noise_tiling = false;
  // The layers' phase function: the Jendersie & d'Eon fit (grey) or the droplets'
  // tabulated Mie phase function per wavelength, with the glory and the fogbow
  // (renderer/model/mie_phase_table.h, renderer/cloud_phase_texture.h).
  model::CloudPhaseModel cloud_phase = model::CloudPhaseModel::kFit;
  // With kMie: whether a frame waits for a new droplet diameter's table (true: files and
  // tests show the Mie phase from the first frame) or draws the fit until it is ready
  // (false: the service, whose frames must not stall; renderer/cloud_phase_texture.h).
  bool wait_for_phase_tables = true;
};

class CloudFieldTextures {
 public:
  explicit CloudFieldTextures(const RendererConfig& config);

  // Uploads the keyframes of blend that changed, their coverage pyramid, and the blended
  // pole values. Returns true when the cloud field the GPU sees changed (a new keyframe,
  // or the blend weight moved by 2 % since the last change).
  bool update(const weather::WeatherTimeline::Blend& blend);

  // Binds the noise volumes and keyframes at their texture units and the coverage pyramid
  // at its storage-buffer binding (gpu::tex, gpu::ssbo).
  void bind() const;

  const GpuResourceSummary& summary() const { return summary_; }
  bool noise_tiling() const { return config_.noise_tiling; }
  std::size_t gpu_bytes() const;  // noise volumes, keyframes, pyramid

 private:
  void upload_coverage_pyramid(const weather::WeatherMap& from, const weather::WeatherMap* to);

  RendererConfig config_;
  GpuResourceSummary summary_{};
  gl::Texture base_noise_, base_noise_max_, detail_noise_, weather_maps_[2];
  // the keyframes' layer-coverage channels (weather::WeatherMap::layer_coverage): the map's
  // size when it has them, else 1 x 1 of zeros
  gl::Texture layer_maps_[2];
  bool layer_maps_full_[2] = {false, false};
  std::uint64_t uploaded_version_[2] = {0, 0};  // keyframe versions in weather_maps_[0], [1]
  float uploaded_blend_ = -1.0f;                // blend weight at the last counted change
  gl::Buffer coverage_pyramid_;
  std::size_t coverage_pyramid_bytes_ = 0;
  std::size_t noise_bytes_ = 0;
};

}  // namespace cloudsvc
