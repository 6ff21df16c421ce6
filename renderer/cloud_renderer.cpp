#include "renderer/cloud_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "geodesy/solar_position.h"
#include "renderer/coverage_cull.h"
#include "renderer/coverage_pyramid.h"
#include "renderer/layers_in_view.h"
#include "renderer/frame_uniforms.h"
#include "renderer/scene_setup.h"
#include "renderer/temporal_reprojection.h"
#include "weather/noise_volumes.h"
#include "weather/weather_map.h"

namespace cloudsvc {

namespace {

gl::Texture upload_noise(const weather::NoiseVolume& v) {
  gl::Texture t = gl::make_texture_3d(GL_R8, v.size, v.size, v.size, GL_REPEAT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage3D(t.id(), 0, 0, 0, 0, v.size, v.size, v.size, GL_RED, GL_UNSIGNED_BYTE, v.data.data());
  return t;
}

struct Counters {
  GLuint density_evals;
  GLuint nonfinite_pixels;
  GLuint cloud_pixels;
};

}  // namespace

CloudRenderer::CloudRenderer(const RendererConfig& config)
    : config_(config),
      march_prog_(gl::ShaderProgram::compute("cloud_march.comp")),
      resolve_prog_(gl::ShaderProgram::compute("cloud_resolve.comp")),
      scene_prog_(gl::ShaderProgram::compute("scene.comp")),
      uniforms_(gl::make_buffer(sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW)),
      temporal_uniforms_(gl::make_buffer(sizeof(TemporalUniforms), nullptr, GL_DYNAMIC_DRAW)),
      counters_(gl::make_buffer(sizeof(Counters), nullptr, GL_DYNAMIC_READ)) {
  const weather::NoiseVolume base = weather::make_base_shape_noise(config.base_noise_size, config.noise_seed);
  facts_.base_quantiles = noise_quantiles(base);
  base_noise_ = upload_noise(base);
  const weather::NoiseVolume detail = weather::make_detail_noise(config.detail_noise_size, config.noise_seed + 1);
  double sum = 0.0;
  for (std::uint8_t v : detail.data) sum += v;
  facts_.detail_mean = static_cast<float>(sum / (255.0 * static_cast<double>(detail.data.size())));
  detail_noise_ = upload_noise(detail);
  static_gpu_bytes_ = base.data.size() + detail.data.size() +
                      2 * static_cast<std::size_t>(config.weather_map_width) * config.weather_map_height * 16 +
                      AtmosphereLuts::gpu_bytes() + GroundShadowMap::gpu_bytes();
  set_weather(weather::Weather{});
}

// Uploads the keyframes around utc_s (only those that changed), sets the blend weight and
// the blended pole values; returns the blend (valid until the timeline next changes).
weather::WeatherTimeline::Blend CloudRenderer::update_weather_textures(double utc_s) {
  const weather::WeatherTimeline::Blend b = timeline_.at(utc_s);
  const weather::WeatherMap* maps[2] = {b.from, b.to};
  bool pyramid_stale = !coverage_pyramid_;
  const std::uint64_t versions[2] = {b.from_version, b.to_version};
  for (int k = 0; k < 2; ++k) {
    if (uploaded_version_[k] == versions[k] && weather_maps_[k]) continue;
    const weather::WeatherMap& m = *maps[k];
    if (!weather_maps_[k]) weather_maps_[k] = gl::make_texture_2d(GL_RGBA32F, m.width, m.height, GL_REPEAT, GL_CLAMP_TO_EDGE);
    glTextureSubImage2D(weather_maps_[k].id(), 0, 0, 0, m.width, m.height, GL_RGBA, GL_FLOAT, m.rgba.data());
    uploaded_version_[k] = versions[k];
    ++weather_generation_;
    pyramid_stale = true;
  }
  if (pyramid_stale) upload_coverage_pyramid(*b.from, b.to != b.from ? b.to : nullptr);
  // a fading keyframe changes the clouds slowly: count steps of 2 % of the blend
  if (std::abs(b.weight - uploaded_blend_) > 0.02f) {
    uploaded_blend_ = static_cast<float>(b.weight);
    ++weather_generation_;
  }
  float south[2][4], north[2][4];
  for (int k = 0; k < 2; ++k) {
    maps[k]->pole_value(false, south[k]);
    maps[k]->pole_value(true, north[k]);
  }
  for (int i = 0; i < 4; ++i) {
    facts_.weather_pole_south[static_cast<size_t>(i)] = south[0][i] + b.weight * (south[1][i] - south[0][i]);
    facts_.weather_pole_north[static_cast<size_t>(i)] = north[0][i] + b.weight * (north[1][i] - north[0][i]);
  }
  facts_.weather_map_height = b.from->height;
  facts_.weather_blend = b.weight;
  return b;
}

// The coverage max-pyramid of the keyframes (renderer/coverage_pyramid.h) into the storage
// buffer shaders/coverage_pyramid.glsl reads; off (the march does not query it) for a map
// too large to pack.
void CloudRenderer::upload_coverage_pyramid(const weather::WeatherMap& from, const weather::WeatherMap* to) {
  const std::vector<std::uint32_t> words = pack_for_gpu(build_coverage_pyramid(from, to));
  facts_.coverage_pyramid = !words.empty();
  // off: a buffer of the block's fixed part and one cell (bound, never read: skips.x = 0)
  const std::size_t bytes = std::max<std::size_t>(words.size(), 4 * kGpuPyramidLevels + 1) * sizeof(std::uint32_t);
  if (!coverage_pyramid_ || bytes != coverage_pyramid_bytes_) {
    coverage_pyramid_ = gl::make_buffer(static_cast<GLsizeiptr>(bytes), nullptr, GL_STATIC_DRAW);
    coverage_pyramid_bytes_ = bytes;
  }
  if (!words.empty()) glNamedBufferSubData(coverage_pyramid_.id(), 0, static_cast<GLsizeiptr>(bytes), words.data());
}

void CloudRenderer::apply_tile(const weather::MapTile& tile, double now_utc_s) {
  // A precondition check, kept on purpose: this is a public API (tests, tools and the
  // service call it), and the timeline's resampling trusts the bounds, size and values. It
  // is the one rule set of weather/map_tile.h that the protocol applies to a WeatherMapTile
  // too, so a tile the service accepted passes it; the second pass costs one sweep over
  // the values, little beside apply_tile's resampling of every keyframe.
  const std::string problem = tile.problem();
  if (!problem.empty()) throw std::invalid_argument("weather tile: " + problem);
  timeline_.apply(tile, now_utc_s);
}

void CloudRenderer::set_weather(const weather::Weather& w) {
  const std::string problem = weather::validate(w);
  if (!problem.empty()) throw std::invalid_argument("invalid weather: " + problem);
  weather_ = w;
  ++weather_generation_;
  wind_anchor_.reset();
  prev_view_.reset();  // new clouds: nothing to reuse
  if (!map_valid_ || map_seed_ != w.map_seed) {
    timeline_.reset(weather::generate_procedural_map(w.map_seed, config_.weather_map_width, config_.weather_map_height));
    map_seed_ = w.map_seed;
    map_valid_ = true;
  }
}

void CloudRenderer::ensure_targets(int w, int h, int divisor) {
  if (!target_ || w != target_w_ || h != target_h_) {
    target_ = gl::make_texture_2d(GL_RGBA32F, w, h, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
    target_w_ = w;
    target_h_ = h;
  }
  const glm::ivec2 c = cloud_buffer_size(w, h, divisor);
  if (fresh_a_ && c.x == cloud_w_ && c.y == cloud_h_) return;
  auto make = [&] { return gl::make_texture_2d(GL_RGBA32F, c.x, c.y, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE); };
  fresh_a_ = make();
  fresh_b_ = make();
  for (int k = 0; k < 2; ++k) {
    cloud_a_[k] = make();
    cloud_b_[k] = make();
  }
  cloud_w_ = c.x;
  cloud_h_ = c.y;
  prev_view_.reset();
}

// Layers with no cloud anywhere this frame can see (renderer/coverage_cull.h) get coverage
// 0 in the uniforms, which the march and the shadow map skip (shaders/cloud_intervals.glsl).
// A change of that set changes the cloud field the shadow map was built from: the
// weather generation is bumped. Returns the set (bit i: layer i).
unsigned CloudRenderer::cull_layers_without_cloud_in_view(FrameUniforms& u, const ViewRequest& view,
                                                          const weather::WeatherTimeline::Blend& b) {
  if (weather_.layers.empty()) return 0;
  // The largest coverage modulation over the cap (both keyframes while one fades in).
  auto max_m = [&](double cap) {
    float m = max_coverage_in_cap(*b.from, view.position.lat_deg, view.position.lon_deg, cap);
    if (b.to && b.to != b.from && b.weight > 0.0f)
      m = std::max(m, max_coverage_in_cap(*b.to, view.position.lat_deg, view.position.lon_deg, cap));
    return m;
  };
  const double cap = cloud_influence_cap_rad(u.planet.x, u.planet.w);
  // Hysteresis: a layer starts being culled only while the cap 10 % wider is clear too, so
  // a camera at the edge of a clear region does not flip the set (and rebuild the shadow
  // map) every frame; one already culled stays so while the cap itself is clear.
  const float m_wide = max_m(std::min(1.1 * cap, 3.14159265358979));
  const float m = culled_layers_ != 0 ? max_m(cap) : m_wide;  // m <= m_wide: only read for culled layers
  unsigned mask = 0;
  const int n = std::min<int>(static_cast<int>(weather_.layers.size()), u.counts.x);
  for (int i = 0; i < n; ++i) {
    const float c = static_cast<float>(weather_.layers[static_cast<size_t>(i)].coverage);
    const bool was = (culled_layers_ >> i) & 1u;
    if (weather::local_coverage(c, was ? m : m_wide) <= 0.0f) {
      mask |= 1u << i;
      u.layers[i].altitude.z = 0.0f;
    }
  }
  // A layer that comes back into reach was left out of the shadow map (and light volume)
  // since it was culled: rebuild them. A newly culled layer has no cloud within reach, so
  // what they hold stays valid.
  if (culled_layers_ & ~mask) ++weather_generation_;
  culled_layers_ = mask;
  return mask;
}

// The cloud march over this frame's fresh cloud pixels, then the temporal resolve into
// cloud_a_/cloud_b_[history_] (the frame and temporal uniforms must be bound; meets_a_layer:
// some ray of the frame meets a layer, classify_frame_rays).
TemporalUniforms CloudRenderer::march_and_resolve(const ViewRequest& view, const RenderQuality& quality,
                                                   bool meets_a_layer) {
  const bool history = prev_view_ && history_usable(*prev_view_, prev_quality_, view, quality);
  std::optional<Reprojection> rep;
  if (history) rep = make_reprojection(*prev_view_, view, weather_, *wind_anchor_);
  const bool fast = fast_motion_.update(rep && fast_cloud_motion(*rep, quality), history);
  const TemporalUniforms tu = make_temporal_uniforms(view, quality, history, rep ? &*rep : nullptr,
                                                     history ? &*prev_view_ : nullptr, fast);
  glNamedBufferSubData(temporal_uniforms_.id(), 0, sizeof(TemporalUniforms), &tu);
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, temporal_uniforms_.id());

  const int prev = history_, next = 1 - history_;
  history_ = next;
  prev_view_ = view;
  prev_view_->reset_history = false;
  prev_quality_ = quality;
  if (weather_.layers.empty() || !meets_a_layer) {
    // No cloud layer, or none that any ray of this frame meets (above a deck looking up:
    // renderer/layers_in_view.h): no march and nothing to resolve. Empty cloud buffer: no
    // in-scatter, transmittance 1. The next frame starts a new history (it marches every
    // pixel), so nothing of this empty buffer is reprojected into a view that meets a layer.
    const float empty_a[4] = {0.0f, 0.0f, 0.0f, 1.0f}, empty_b[4] = {1e7f, 0.0f, -1.0f, 0.0f};
    glClearTexImage(cloud_a_[next].id(), 0, GL_RGBA, GL_FLOAT, empty_a);
    glClearTexImage(cloud_b_[next].id(), 0, GL_RGBA, GL_FLOAT, empty_b);
    prev_view_.reset();
    TemporalUniforms skipped = tu;
    skipped.grid.x = 0;  // nothing marched
    return skipped;
  }

  const int stride = tu.grid.x;
  march_prog_.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, coverage_pyramid_.id());
  glBindImageTexture(0, fresh_a_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, fresh_b_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  timer_.begin(1);
  dispatch_2d((cloud_w_ + stride - 1) / stride, (cloud_h_ + stride - 1) / stride);
  timer_.end();

  if (stride == 1 && tu.grid.w == 0) {
    // Every pixel marched and no history: the resolve would copy the fresh samples as they
    // are (cloud_resolve.comp, no-history branch), so the fresh buffers become this
    // frame's cloud buffer instead.
    std::swap(fresh_a_, cloud_a_[next]);
    std::swap(fresh_b_, cloud_b_[next]);
    return tu;
  }
  resolve_prog_.use();
  glBindTextureUnit(10, fresh_a_.id());
  glBindTextureUnit(11, fresh_b_.id());
  glBindTextureUnit(12, cloud_a_[prev].id());
  glBindTextureUnit(13, cloud_b_[prev].id());
  glBindImageTexture(0, cloud_a_[next].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, cloud_b_[next].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  timer_.begin(2);
  dispatch_2d(cloud_w_, cloud_h_);
  timer_.end();
  return tu;
}

FrameImage CloudRenderer::render(const ViewRequest& view, const RenderQuality& quality) {
  if (view.width <= 0 || view.height <= 0) throw std::invalid_argument("render: empty image size");
  const auto start = std::chrono::steady_clock::now();
  const int divisor = std::clamp(quality.cloud_resolution_divisor, 1, 8);
  ensure_targets(view.width, view.height, divisor);

  if (!wind_anchor_) wind_anchor_ = WindAnchor{view.position, view.unix_time_s};
  const weather::WeatherTimeline::Blend blend = update_weather_textures(view.unix_time_s);
  FrameUniforms u = make_frame_uniforms(view, weather_, quality, facts_, &*wind_anchor_);
  const unsigned culled = cull_layers_without_cloud_in_view(u, view, blend);
  const AtmosphereLuts::ViewLutUpdate view_luts = atmosphere_.plan_view_dependent(u);  // sets u.ap_*
  glNamedBufferSubData(uniforms_.id(), 0, sizeof(FrameUniforms), &u);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, uniforms_.id());
  const Counters zero{0, 0, 0};
  glNamedBufferSubData(counters_.id(), 0, sizeof(Counters), &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counters_.id());

  timer_.reset();
  timer_.begin(0);
  atmosphere_.recompute(view_luts);
  timer_.end();
  atmosphere_.bind_for_scene();
  glBindTextureUnit(3, base_noise_.id());
  glBindTextureUnit(4, detail_noise_.id());
  glBindTextureUnit(5, weather_maps_[0].id());
  glBindTextureUnit(9, weather_maps_[1].id());
  timer_.begin(4);
  if (view.reset_history) shadow_map_.invalidate();  // a teleport starts from nothing
  // The map serves the ground's pixels (and the light volume built with it, the march's):
  // not updated while no ray sees the ground and none that needs the volume is marched.
  const FrameRays rays = classify_frame_rays(u);
  const bool shadow_needed = rays.sees_ground || (quality.light_volume && rays.meets_a_layer);
  const bool shadow_rebuilt = shadow_map_.update(view, u, weather_, *wind_anchor_, weather_generation_,
                                                 !quality.ground_shadow_map, quality.light_volume, shadow_needed);
  timer_.end();
  const TemporalUniforms tu = march_and_resolve(view, quality, rays.meets_a_layer);

  scene_prog_.use();
  glBindTextureUnit(12, cloud_a_[history_].id());  // the composite needs the radiance and transmittance only
  glBindImageTexture(0, target_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  timer_.begin(3);
  dispatch_2d(view.width, view.height);
  timer_.end();
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  FrameImage img;
  const auto readback_start = std::chrono::steady_clock::now();
  img.width = view.width;
  img.height = view.height;
  img.rgba.resize(static_cast<size_t>(view.width) * view.height * 4);
  glGetTextureImage(target_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(img.rgba.size() * sizeof(float)),
                    img.rgba.data());
  Counters c{};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof(Counters), &c);
  const auto end = std::chrono::steady_clock::now();

  const geo::SolarPosition sp = geo::solar_position(view.unix_time_s, view.position.lat_deg, view.position.lon_deg);
  img.stats.view_luts_recomputed = view_luts.sky_view || view_luts.aerial_perspective;
  img.stats.sky_view_recomputed = view_luts.sky_view;
  img.stats.history_used = tu.grid.w != 0;
  img.stats.shadow_map_rebuilt = shadow_rebuilt;
  img.stats.layers_without_cloud_in_view = static_cast<int>(__builtin_popcount(culled));
  img.stats.shadow_map_ms = timer_.ms(4);
  img.stats.marched_fraction = tu.grid.x == 0 ? 0.0 : 1.0 / (static_cast<double>(tu.grid.x) * tu.grid.x);
  img.stats.gpu_memory_bytes = static_cast<std::int64_t>(
      static_gpu_bytes_ + coverage_pyramid_bytes_ + static_cast<std::size_t>(target_w_) * target_h_ * 16 +
      6 * static_cast<std::size_t>(cloud_w_) * cloud_h_ * 16);
  img.stats.render_ms = std::chrono::duration<double, std::milli>(end - start).count();
  img.stats.readback_ms = std::chrono::duration<double, std::milli>(end - readback_start).count();
  img.stats.luts_ms = timer_.ms(0);
  img.stats.march_ms = timer_.ms(1);
  img.stats.resolve_ms = timer_.ms(2);
  img.stats.composite_ms = timer_.ms(3);
  img.stats.sun_elevation_deg = sp.elevation_deg;
  img.stats.sun_azimuth_deg = sp.azimuth_deg;
  img.stats.cloud_pixels = c.cloud_pixels;
  img.stats.nonfinite_pixels = c.nonfinite_pixels;
  img.stats.density_evals_per_pixel =
      static_cast<double>(c.density_evals) / (static_cast<double>(view.width) * view.height);
  return img;
}

}  // namespace cloudsvc
