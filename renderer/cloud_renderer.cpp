#include "renderer/cloud_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "renderer/coverage_cull.h"
#include "renderer/density_programs.h"
#include "renderer/frame_uniforms_packing.h"
#include "renderer/layers_in_view.h"
#include "weather/weather_map.h"

namespace cloudsvc {

namespace {
enum TimedPass { kLutsPass = 0, kMarchPass = 1, kResolvePass = 2, kCompositePass = 3, kShadowMapPass = 4 };

// Every layer of b has the wind of a's at its index, and there are as many.
bool same_winds(const weather::Weather& a, const weather::Weather& b) {
  if (a.layers.size() != b.layers.size()) return false;
  for (std::size_t i = 0; i < a.layers.size(); ++i)
    if (!(a.layers[i].wind == b.layers[i].wind)) return false;
  return true;
}
}  // namespace

CloudRenderer::CloudRenderer(const RendererConfig& config)
    : config_(config),
      ground_albedo_map_(config.weather_map_width, config.weather_map_height),
      field_(config),
      march_(config.cloud_phase) {
  if (config.cumulus_domes) domes_ = std::make_unique<DomeField>();
  if (config.cloud_phase == model::CloudPhaseModel::kMie) phase_ = std::make_unique<CloudPhaseTexture>(config.wait_for_phase_tables);
  set_weather(weather::Weather{});
}

void CloudRenderer::apply_tile(const weather::MapTile& tile, double now_utc_s) {
  // A precondition check, kept on purpose: this is a public API (tests, tools and the
  // service call it), and the timeline's resampling trusts the bounds, size and values. It
  // is the one rule set of weather/map_tile.h that the protocol applies to a WeatherMapTile
  // too, so a tile the service accepted passes it; the second pass costs one sweep over
  // the values, little beside apply_tile's resampling of every keyframe.
  const std::string problem = tile.problem();
  if (!problem.empty()) throw std::invalid_argument("weather tile: " + problem);
  if ((tile.channels & weather::kWeatherMapTileChannels) || tile.layer_channels) timeline_.apply(tile, now_utc_s);
  if (tile.channels & weather::kGroundAlbedoTileChannel) {
    ground_albedo_map_.apply(tile);
    reset_history();  // the clouds' light from the ground changes at once
  }
}

void CloudRenderer::adopt_weather(const weather::Weather& w, bool keep_drift) {
  const std::string problem = weather::validate(w);
  if (!problem.empty()) throw std::invalid_argument("invalid weather: " + problem);
  weather_ = w;
  ++weather_generation_;
  if (!keep_drift) wind_anchor_.reset();
  reset_history();  // new clouds: nothing to reuse
}

void CloudRenderer::update_weather(const weather::Weather& w) {
  if (map_valid_ && !forecast_map_ && map_seed_ == w.map_seed) {
    if (w == weather_) return;  // resent: nothing changes
    adopt_weather(w, same_winds(weather_, w));
    return;
  }
  set_weather(w);
}

void CloudRenderer::set_weather(const weather::Weather& w) {
  adopt_weather(w);
  if (!map_valid_ || map_seed_ != w.map_seed || forecast_map_) {
    timeline_.reset(weather::generate_procedural_map(w.map_seed, config_.weather_map_width, config_.weather_map_height));
    map_seed_ = w.map_seed;
    map_valid_ = true;
    forecast_map_ = false;
  }
}

void CloudRenderer::set_forecast(const weather::Weather& w, weather::WeatherMap map) {
  set_forecast(w, {{0.0, std::move(map)}});
}

void CloudRenderer::set_forecast(const weather::Weather& w, std::vector<std::pair<double, weather::WeatherMap>> keyframes) {
  take_forecast(w, std::move(keyframes), false);
}

void CloudRenderer::update_forecast(const weather::Weather& w, weather::WeatherMap map) {
  update_forecast(w, {{0.0, std::move(map)}});
}

void CloudRenderer::update_forecast(const weather::Weather& w,
                                    std::vector<std::pair<double, weather::WeatherMap>> keyframes) {
  take_forecast(w, std::move(keyframes), forecast_map_ && same_winds(weather_, w));
}

void CloudRenderer::take_forecast(const weather::Weather& w, std::vector<std::pair<double, weather::WeatherMap>> keyframes,
                                  bool keep_drift) {
  for (const auto& [t, map] : keyframes)
    if (map.width != config_.weather_map_width || map.height != config_.weather_map_height || !map.has_layer_coverage())
      throw std::invalid_argument("forecast map: expected " + std::to_string(config_.weather_map_width) + " x " +
                                  std::to_string(config_.weather_map_height) + " texels with layer coverage");
  const std::string problem = weather::validate(w);
  if (!problem.empty()) throw std::invalid_argument("invalid weather: " + problem);
  // the same timeline: its keyframe versions keep counting, so the GPU uploads the new ones
  timeline_.reset(std::move(keyframes));  // throws before it changes anything
  adopt_weather(w, keep_drift);
  map_seed_ = w.map_seed;
  map_valid_ = true;
  forecast_map_ = true;
}

void CloudRenderer::update_forecast_layers(const weather::Weather& w) {
  if (!forecast_map_) throw std::logic_error("update_forecast_layers without a forecast");
  if (w == weather_) return;
  adopt_weather(w, same_winds(weather_, w));
}

// Layers with no cloud anywhere this frame can see (renderer/coverage_cull.h) are marked
// culled in the frame: coverage 0 in the uniforms, which the march and the shadow map skip
// (shaders/cloud_intervals.glsl). A change of that set changes the cloud field the shadow
// map was built from: the weather generation is bumped.
void CloudRenderer::cull_layers_without_cloud_in_view(FrameContext& frame, const weather::WeatherTimeline::Blend& b) {
  if (frame.layer_count == 0) return;
  const double lat = frame.view.position.lat_deg, lon = frame.view.position.lon_deg;
  // The largest coverage modulation over the cap (both keyframes while one fades in).
  auto max_m = [&](double cap) {
    float m = max_coverage_in_cap(*b.from, lat, lon, cap);
    if (b.to && b.to != b.from && b.weight > 0.0f) m = std::max(m, max_coverage_in_cap(*b.to, lat, lon, cap));
    return m;
  };
  const double cap = cloud_influence_cap_rad(frame.shell_radius_m, frame.march_reach_m);
  // Hysteresis: a layer starts being culled only while the cap 10 % wider is clear too, so
  // a camera at the edge of a clear region does not flip the set (and rebuild the shadow
  // map) every frame; one already culled stays so while the cap itself is clear.
  const float m_wide = max_m(std::min(1.1 * cap, M_PI));
  const float m = culled_layers_ != 0 ? max_m(cap) : m_wide;  // m <= m_wide: only read for culled layers
  for (int i = 0; i < frame.layer_count; ++i) {
    LayerFrame& lf = frame.layers[static_cast<size_t>(i)];
    const bool was = (culled_layers_ >> i) & 1u;
    lf.culled = weather::layer_local_coverage(lf.layer.coverage_channel, static_cast<float>(lf.layer.coverage),
                                              was ? m : m_wide) <= 0.0f;
  }
  // A layer that comes back into reach was left out of the shadow map (and light volume)
  // since it was culled: rebuild them. A newly culled layer has no cloud within reach, so
  // what they hold stays valid.
  const unsigned mask = frame.culled_mask();
  if (culled_layers_ & ~mask) ++weather_generation_;
  culled_layers_ = mask;
}

void CloudRenderer::reset_history() {
  for (auto& [id, channel] : channels_) channel.cloud_buffer.reset_history();
}

TemporalPlan CloudRenderer::march_and_resolve(const FrameContext& frame, const RenderQuality& quality,
                                              bool meets_a_layer, const CloudPassInputs& inputs,
                                              CloudBuffer& cloud_buffer) {
  TemporalPlan plan = cloud_buffer.start_frame(frame, quality);
  if (weather_.layers.empty() || !meets_a_layer) {
    // No cloud layer, or none that any ray of this frame meets (above a deck looking up:
    // renderer/layers_in_view.h): no march and nothing to resolve; the next frame starts
    // a new history, so nothing of this empty buffer is reprojected into a view that meets
    // a layer.
    cloud_buffer.clear_current();
    plan.stride = 0;  // nothing marched
    return plan;
  }
  timer_.begin(kMarchPass);
  march_.run(inputs, shadow_map_, cloud_buffer, plan);
  timer_.end();
  if (plan.stride == 1 && !plan.history) {
    // Every pixel marched and no history: the resolve would copy the fresh samples as they
    // are (cloud_resolve.comp, no-history branch).
    cloud_buffer.take_fresh_as_current();
    return plan;
  }
  timer_.begin(kResolvePass);
  resolve_.run(inputs.frame, cloud_buffer);
  timer_.end();
  return plan;
}

FrameImage CloudRenderer::render(const ViewRequest& view, const RenderQuality& quality) {
  if (view.width <= 0 || view.height <= 0) throw std::invalid_argument("render: empty image size");
  const auto start = std::chrono::steady_clock::now();
  Channel& channel = channels_[view.channel];
  channel.cloud_buffer.ensure_size(view.width, view.height, std::clamp(quality.cloud_resolution_divisor, 1, 8));
  channel.target.ensure_size(view.width, view.height);
  if (!wind_anchor_) wind_anchor_ = WindAnchor{view.position, view.unix_time_s};
  const weather::WeatherTimeline::Blend blend = timeline_.at(view.unix_time_s);
  if (field_.update(blend)) ++weather_generation_;

  // 1. The frame's state, once, in double; every step below reads it, the uniforms last.
  FrameContext frame = make_frame_context(view, weather_, *wind_anchor_);
  cull_layers_without_cloud_in_view(frame, blend);
  // Dome layers with cloud in reach: the frame's programs carry the dome path only then
  // (renderer/density_programs.h).
  bool draws_domes = false;
  if (domes_)
    for (int i = 0; i < frame.layer_count; ++i) {
      LayerFrame& lf = frame.layers[static_cast<std::size_t>(i)];
      lf.domes = weather::uses_domes(lf.layer.type) && !lf.culled;
      draws_domes = draws_domes || lf.domes;
    }
  const AtmosphereLuts::ViewLutUpdate view_luts = atmosphere_.plan_view_dependent(frame);  // sets frame.ap
  const FrameRays rays = classify_frame_rays(frame);
  ground_albedo_.update(ground_albedo_map_);
  GpuResourceSummary resources = field_.summary();
  ground_albedo_.describe(resources);
  const FrameUniforms uniforms = pack_frame_uniforms(frame, quality, resources);
  frame_buffers_.start_frame(uniforms);
  if (draws_domes) {
    field_.bind();  // the ring fill reads the weather map
    domes_->update(frame, weather_, weather_generation_, uniforms);
  }
  if (phase_) phase_->update(frame);
  const CloudPassInputs inputs{frame_buffers_, field_, atmosphere_, ms_source_, ground_albedo_,
                               draws_domes ? domes_.get() : nullptr, density_loops_fit(quality), phase_.get()};

  timer_.reset();
  timer_.begin(kLutsPass);  // 2.
  atmosphere_.recompute(view_luts, frame_buffers_);
  timer_.end();
  timer_.begin(kShadowMapPass);  // 3.
  if (view.reset_history) shadow_map_.invalidate();  // a teleport starts from nothing
  // The map serves the ground's pixels, the march's layers under another (their light from
  // above) and the light and column volumes built with it (the march's): not updated while
  // no ray sees the ground and none that reads the map or a volume is marched.
  // The diffuse light's column depths: from the column volume, or marched per lit sample
  // where there is no map to build it with or the quality asks for that.
  const int marched_columns = marched_column_steps(quality);
  const int volume_column_steps = quality.column_steps - marched_columns;
  const bool volumes_read = quality.light_volume || volume_column_steps > 0;
  const bool shadow_needed =
      rays.sees_ground || rays.meets_a_layer_under_another || (volumes_read && rays.meets_a_layer);
  const bool shadow_rebuilt =
      shadow_map_.update(frame, inputs, weather_generation_, quality.light_steps, !quality.ground_shadow_map,
                         quality.light_volume, volume_column_steps, marched_columns, shadow_needed);
  timer_.end();
  const TemporalPlan plan = march_and_resolve(frame, quality, rays.meets_a_layer, inputs, channel.cloud_buffer);  // 4., 5.
  timer_.begin(kCompositePass);  // 6.
  composite_.run(inputs, shadow_map_, channel.cloud_buffer, channel.target, !quality.ground_shadow_map);
  timer_.end();

  FrameImage img;
  const auto readback_start = std::chrono::steady_clock::now();
  channel.target.read_back(img);
  const FrameCounters counters = frame_buffers_.read_counters();
  const auto end = std::chrono::steady_clock::now();
  img.stats = frame_stats(frame, view_luts, plan, shadow_rebuilt, counters);
  img.stats.render_ms = std::chrono::duration<double, std::milli>(end - start).count();
  img.stats.readback_ms = std::chrono::duration<double, std::milli>(end - readback_start).count();
  if (img.stats.loop_capped_invocations > 0 && !warned_loop_cap_) {
    std::fprintf(stderr,
                 "cloudsvc: warning: the GL driver cut %lld shader invocations short (llvmpipe runs at most 65535 loop "
                 "iterations per invocation): clouds are missing or wrongly lit; use fewer primary or light steps "
                 "(FrameStats::loop_capped_invocations; warned once)\n",
                 static_cast<long long>(img.stats.loop_capped_invocations));
    warned_loop_cap_ = true;
  }
  return img;
}

FrameStats CloudRenderer::frame_stats(const FrameContext& frame, const AtmosphereLuts::ViewLutUpdate& view_luts,
                                      const TemporalPlan& plan, bool shadow_rebuilt,
                                      const FrameCounters& counters) const {
  FrameStats s;
  s.view_luts_recomputed = view_luts.sky_view || view_luts.aerial_perspective;
  s.sky_view_recomputed = view_luts.sky_view;
  s.history_used = plan.history;
  s.shadow_map_rebuilt = shadow_rebuilt;
  s.layers_without_cloud_in_view = static_cast<int>(__builtin_popcount(frame.culled_mask()));
  for (int i = 0; i < frame.layer_count; ++i) s.dome_layers += frame.layers[static_cast<std::size_t>(i)].domes ? 1 : 0;
  s.phase_tables_pending = phase_ ? phase_->pending_rows() : 0;
  s.marched_fraction = plan.stride == 0 ? 0.0 : plan.marched_fraction();
  std::size_t channel_bytes = 0;  // every channel's buffers stay resident
  for (const auto& [id, channel] : channels_) channel_bytes += channel.target.gpu_bytes() + channel.cloud_buffer.gpu_bytes();
  s.gpu_memory_bytes = static_cast<std::int64_t>(field_.gpu_bytes() + AtmosphereLuts::gpu_bytes() +
                                                 MsSourceTextures::gpu_bytes() + ground_albedo_.gpu_bytes() +
                                                 shadow_map_.gpu_bytes() +
                                                 channel_bytes +
                                                 (phase_ ? CloudPhaseTexture::gpu_bytes() : 0));
  s.luts_ms = timer_.ms(kLutsPass);
  s.march_ms = timer_.ms(kMarchPass);
  s.resolve_ms = timer_.ms(kResolvePass);
  s.composite_ms = timer_.ms(kCompositePass);
  s.shadow_map_ms = timer_.ms(kShadowMapPass);
  s.sun_elevation_deg = frame.sun.elevation_deg;
  s.sun_azimuth_deg = frame.sun.azimuth_deg;
  s.cloud_pixels = counters.cloud_pixels;
  s.nonfinite_pixels = counters.nonfinite_pixels;
  s.loop_capped_invocations = counters.loop_capped_invocations;
  s.density_evals_per_pixel =
      static_cast<double>(counters.density_evals) / (static_cast<double>(frame.view.width) * frame.view.height);
  return s;
}

}  // namespace cloudsvc
