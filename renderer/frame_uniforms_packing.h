// Packs a frame's state (renderer/frame_context.h, double precision) into the GPU's frame
// uniforms (renderer/frame_uniforms.h): the last, write-only step of a frame's CPU work.
// Also the facts about the GPU resources the uniforms describe. No GL here.
#pragma once

#include <array>
#include <cstdint>

#include "renderer/api/render_quality.h"
#include "renderer/frame_context.h"
#include "renderer/frame_uniforms.h"
#include "weather/noise_volumes.h"

namespace cloudsvc {

// Values of a noise volume below which a fraction i / 15 of its texels lie (i = 0..15).
// The shader turns a layer's coverage c into the base-noise threshold Q(1 - c), so that
// coverage is the fraction of horizontal area covered by cloud at mid-profile.
using NoiseQuantiles = std::array<float, 16>;
NoiseQuantiles noise_quantiles(const weather::NoiseVolume& v);

// What the frame uniforms say about the GPU resources bound with them.
struct GpuResourceSummary {
  NoiseQuantiles base_quantiles{};      // of the base shape noise
  float base_mean = 0.5f;               // mean value of the base shape noise volume
  float detail_mean = 0.5f;             // mean value of the detail noise volume
  std::uint32_t noise_seed = 1;         // the volumes' seed (RendererConfig::noise_seed): tiling seeds
  std::array<float, 4> weather_pole_south{0.5f, 0.5f, 0.5f, 0.0f};
  std::array<float, 4> weather_pole_north{0.5f, 0.5f, 0.5f, 0.0f};
  std::array<float, 4> layer_coverage_pole_south{};  // the keyframes' layer-coverage channels at the poles
  std::array<float, 4> layer_coverage_pole_north{};
  int weather_map_height = 1;
  float weather_blend = 0.0f;     // weight of the second weather keyframe (weather_timeline.h)
  bool coverage_pyramid = false;  // the coverage max-pyramid is bound (renderer/coverage_pyramid.h)
  // Tiles have set the ground's albedo somewhere (renderer/ground_albedo_texture.h), and the
  // map's (R, G) at the south pole, then the north's.
  bool ground_albedo_map = false;
  std::array<float, 4> ground_albedo_poles{};
};

FrameUniforms pack_frame_uniforms(const FrameContext& frame, const RenderQuality& quality,
                                  const GpuResourceSummary& resources);

}  // namespace cloudsvc
