// The GPU renderer: draws one ViewRequest per call as a sequence of passes, each of which
// binds what it reads (renderer/cloud_pass_inputs.h):
//   1. the frame's state in double (renderer/frame_context.h): culling, ray classification,
//      LUT planning, then the packed frame uniforms (write-only);
//   2. the camera-dependent atmosphere LUTs (renderer/atmosphere_luts.h);
//   3. the ground shadow map and light volume (renderer/ground_shadow_map.h);
//   4. the cloud march over this frame's fresh cloud pixels (renderer/cloud_march_pass.h);
//   5. the temporal resolve (renderer/cloud_resolve_pass.h);
//   6. the composite over sky and ground, read back (renderer/composite_pass.h).
// The caller owns the GL context and must keep it current on the calling thread (the
// service's render thread alone owns it).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>

#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"
#include "renderer/atmosphere_luts.h"
#include "renderer/cloud_buffer.h"
#include "renderer/cloud_field_textures.h"
#include "renderer/cloud_phase_texture.h"
#include "renderer/dome_field.h"
#include "renderer/cloud_march_pass.h"
#include "renderer/cloud_resolve_pass.h"
#include "renderer/composite_pass.h"
#include "renderer/frame_target.h"
#include "renderer/frame_buffers.h"
#include "renderer/frame_context.h"
#include "renderer/gl/pass_timer.h"
#include "renderer/ground_albedo_texture.h"
#include "renderer/ground_shadow_map.h"
#include "weather/cloud_layer.h"
#include "weather/ground_albedo_map.h"
#include "weather/weather_timeline.h"
#include "weather/wind_drift.h"

namespace cloudsvc {

class CloudRenderer {
 public:
  explicit CloudRenderer(const RendererConfig& config = {});

  // Sets the weather; regenerates the global weather map only when its seed changes.
  // The next rendered view becomes the wind anchor (weather/wind_drift.h).
  void set_weather(const weather::Weather& w);
  // set_weather for a service whose weather changes under a moving view: a weather equal to
  // the current one changes nothing (hosts resend theirs: the history and the drift go on),
  // and where every layer keeps its wind the clouds drift on from where they are (the wind
  // anchor stays; a wind that changes restarts the drift from the next view, as set_weather).
  void update_weather(const weather::Weather& w);
  const weather::Weather& weather() const { return weather_; }
  // The wind anchor of the frames now drawn (none before the first view after a restart).
  const std::optional<WindAnchor>& wind_anchor() const { return wind_anchor_; }

  // Sets forecast weather (weather/forecast_frame.h): layers that read the layer-coverage
  // channels of the maps, which replace the weather map's keyframes (one map for now, or
  // keyframes at their valid times, up to WeatherTimeline::kMaxKeyframes; each of the
  // renderer's size, weather_map_width x weather_map_height of the RendererConfig, with
  // layer coverage). Throws std::invalid_argument for a weather validate() rejects or maps
  // that break those rules. set_weather afterwards returns to the procedural map.
  void set_forecast(const weather::Weather& w, weather::WeatherMap map);
  void set_forecast(const weather::Weather& w, std::vector<std::pair<double, weather::WeatherMap>> keyframes);
  // set_forecast for a running service (the host's layers changed, or time moved on to other
  // keyframes): where every layer keeps its wind the clouds drift on from where they are, as
  // in update_weather.
  void update_forecast(const weather::Weather& w, weather::WeatherMap map);
  void update_forecast(const weather::Weather& w, std::vector<std::pair<double, weather::WeatherMap>> keyframes);
  // New layers for the forecast's keyframes (the region moved); std::logic_error without a
  // forecast. Like update_weather: equal layers change nothing, unchanged winds keep the drift.
  void update_forecast_layers(const weather::Weather& w);
  bool has_forecast() const { return forecast_map_; }
  int weather_map_width() const { return config_.weather_map_width; }
  int weather_map_height() const { return config_.weather_map_height; }

  // Streams a weather-map tile in (weather/weather_timeline.h): its weather channels fade
  // in over time instead of popping; its ground-albedo channel, if any, applies from the
  // next frame (weather/ground_albedo_map.h; kept when set_weather changes the weather).
  // now_utc_s is the current time. Throws std::invalid_argument ("weather tile: " +
  // problem()) when the tile breaks the rules of weather/map_tile.h.
  void apply_tile(const weather::MapTile& tile, double now_utc_s);
  const weather::GroundAlbedoMap& ground_albedo_map() const { return ground_albedo_map_; }
  std::size_t weather_keyframes() const { return timeline_.keyframe_count(); }

  // Renders one view and reads it back (rows from the top). Consecutive views of a channel
  // (ViewRequest::channel) reuse the cloud buffer of that channel's previous one when
  // quality.temporal_stride > 1 and the history is usable (renderer/temporal_reprojection.h);
  // the views of several channels at one time and place share the weather field, the ground
  // shadow map and the sky LUT, so that only their view-dependent passes run per view.
  FrameImage render(const ViewRequest& view, const RenderQuality& quality = {});

  // Drops every channel's temporal history: the next frames march every cloud pixel.
  void reset_history();
  // Frees a channel's buffers (a view the host removed).
  void drop_channel(int channel) { channels_.erase(channel); }

 private:
  void cull_layers_without_cloud_in_view(FrameContext& frame, const weather::WeatherTimeline::Blend& blend);
  // Steps 4-5; returns the frame's temporal plan (stride 0: nothing marched).
  // A display channel's own buffers: its temporal history and its frame.
  struct Channel {
    CloudBuffer cloud_buffer;
    FrameTarget target;
  };
  TemporalPlan march_and_resolve(const FrameContext& frame, const RenderQuality& quality, bool meets_a_layer,
                                 const CloudPassInputs& inputs, CloudBuffer& cloud_buffer);
  FrameStats frame_stats(const FrameContext& frame, const AtmosphereLuts::ViewLutUpdate& view_luts,
                         const TemporalPlan& plan, bool shadow_rebuilt, const FrameCounters& counters) const;

  RendererConfig config_;
  weather::Weather weather_;
  std::uint32_t map_seed_ = 0;
  bool map_valid_ = false;
  bool forecast_map_ = false;  // the keyframes are a forecast's (set_forecast)
  // validate, take w, start the clouds' history afresh; keep_drift: keep the wind anchor
  void adopt_weather(const weather::Weather& w, bool keep_drift = false);
  void take_forecast(const weather::Weather& w, std::vector<std::pair<double, weather::WeatherMap>> keyframes,
                     bool keep_drift);
  weather::WeatherTimeline timeline_;
  weather::GroundAlbedoMap ground_albedo_map_;
  std::optional<WindAnchor> wind_anchor_;  // latched at the first view after set_weather
  bool warned_loop_cap_ = false;           // the loop-cap warning (render) is printed once
  std::uint64_t weather_generation_ = 0;   // bumped by every change of the cloud field's inputs
  unsigned culled_layers_ = 0;             // bit i: layer i had no cloud within reach last frame

  CloudFieldTextures field_;
  std::unique_ptr<DomeField> domes_;  // config_.cumulus_domes only
  std::unique_ptr<CloudPhaseTexture> phase_;  // config_.cloud_phase == kMie only
  FrameBuffers frame_buffers_;
  AtmosphereLuts atmosphere_;
  MsSourceTextures ms_source_;
  GroundAlbedoTexture ground_albedo_;
  GroundShadowMap shadow_map_;
  std::map<int, Channel> channels_;  // by ViewRequest::channel
  CloudMarchPass march_;
  CloudResolvePass resolve_;
  CompositePass composite_;
  gl::PassTimer timer_;  // passes: 0 LUTs, 1 march, 2 resolve, 3 composite, 4 shadow map
};

}  // namespace cloudsvc
