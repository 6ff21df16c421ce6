// The GPU renderer: owns every GL object (noise volumes, weather map, atmosphere LUTs,
// frame target) and draws one ViewRequest per call. The caller owns the GL context and
// must keep it current on the calling thread (DESIGN.md §1: the render thread alone owns it).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "renderer/atmosphere_luts.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/ground_shadow_map.h"
#include "renderer/gl/pass_timer.h"
#include "renderer/gl/shader_program.h"
#include "renderer/render_types.h"
#include "renderer/scene_setup.h"
#include "renderer/temporal_reprojection.h"
#include "renderer/temporal_uniforms.h"
#include "weather/cloud_layer.h"
#include "weather/weather_timeline.h"

namespace cloudsvc {

struct RendererConfig {
  int base_noise_size = 128;   // Perlin-Worley base shape volume edge
  int detail_noise_size = 32;  // Worley detail volume edge
  std::uint32_t noise_seed = 1;
  int weather_map_width = 1024;  // global map, 0.35 deg per texel
  int weather_map_height = 512;
};

class CloudRenderer {
 public:
  explicit CloudRenderer(const RendererConfig& config = {});

  // Sets the weather; regenerates the global weather map only when its seed changes.
  // The next rendered view becomes the wind anchor (renderer/wind_drift.h).
  void set_weather(const weather::Weather& w);
  const weather::Weather& weather() const { return weather_; }

  // Streams a weather-map tile in (weather/weather_timeline.h): it fades in over time
  // instead of popping. now_utc_s is the current time. Throws std::invalid_argument
  // ("weather tile: " + problem()) when the tile breaks the rules of weather/map_tile.h.
  void apply_tile(const weather::MapTile& tile, double now_utc_s);
  std::size_t weather_keyframes() const { return timeline_.keyframe_count(); }

  // Renders one view and reads it back (rows from the top). Consecutive views reuse the
  // cloud buffer of the previous one when quality.temporal_stride > 1 and the history is
  // usable (renderer/temporal_reprojection.h).
  FrameImage render(const ViewRequest& view, const RenderQuality& quality = {});

  // Drops the temporal history: the next frame marches every cloud pixel.
  void reset_history() { prev_view_.reset(); }

 private:
  weather::WeatherTimeline::Blend update_weather_textures(double utc_s);
  void upload_coverage_pyramid(const weather::WeatherMap& from, const weather::WeatherMap* to);
  void ensure_targets(int w, int h, int divisor);
  TemporalUniforms march_and_resolve(const ViewRequest& view, const RenderQuality& quality, bool meets_a_layer);
  unsigned cull_layers_without_cloud_in_view(FrameUniforms& u, const ViewRequest& view,
                                             const weather::WeatherTimeline::Blend& blend);

  RendererConfig config_;
  weather::Weather weather_;
  std::uint32_t map_seed_ = 0;
  bool map_valid_ = false;
  AtmosphereLuts atmosphere_;
  GroundShadowMap shadow_map_;
  std::uint64_t weather_generation_ = 0;  // bumped by every change of the cloud field's inputs
  unsigned culled_layers_ = 0;            // bit i: layer i had no cloud within reach last frame
  float uploaded_blend_ = -1.0f;          // keyframe blend weight the shadow map saw
  gl::ShaderProgram march_prog_, resolve_prog_, scene_prog_;
  ResourceFacts facts_{};
  std::optional<WindAnchor> wind_anchor_;  // latched at the first view after set_weather
  weather::WeatherTimeline timeline_;
  std::uint64_t uploaded_version_[2] = {0, 0};  // keyframe versions in weather_maps_[0], [1]
  gl::Texture base_noise_, detail_noise_, weather_maps_[2], target_;
  // Cloud buffer (shaders/temporal_uniforms.glsl): this frame's fresh samples and the
  // resolved buffer of the previous and the current frame (ping-pong, index history_).
  gl::Texture fresh_a_, fresh_b_, cloud_a_[2], cloud_b_[2];
  int history_ = 0;
  std::optional<ViewRequest> prev_view_;  // the last frame, while its buffer may be reused
  RenderQuality prev_quality_;
  FastMotionHold fast_motion_;  // 1/4 px instead of 1/16 while the clouds move fast
  gl::Buffer uniforms_, temporal_uniforms_, counters_;
  gl::Buffer coverage_pyramid_;  // renderer/coverage_pyramid.h of the keyframes in weather_maps_
  std::size_t coverage_pyramid_bytes_ = 0;
  int target_w_ = 0, target_h_ = 0, cloud_w_ = 0, cloud_h_ = 0;
  gl::PassTimer timer_;  // passes: 0 LUTs, 1 march, 2 resolve, 3 composite, 4 shadow map
  std::size_t static_gpu_bytes_ = 0;  // noise volumes, weather maps, atmosphere LUTs
};

}  // namespace cloudsvc
