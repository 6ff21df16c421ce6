#include "renderer/cloud_renderer.h"

#include <chrono>
#include <stdexcept>

#include "geodesy/solar_position.h"
#include "renderer/frame_uniforms.h"
#include "renderer/scene_setup.h"
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
      scene_prog_(gl::ShaderProgram::compute("scene.comp")),
      detail_noise_(upload_noise(weather::make_detail_noise(config.detail_noise_size, config.noise_seed + 1))),
      uniforms_(gl::make_buffer(sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW)),
      counters_(gl::make_buffer(sizeof(Counters), nullptr, GL_DYNAMIC_READ)) {
  const weather::NoiseVolume base = weather::make_base_shape_noise(config.base_noise_size, config.noise_seed);
  facts_.base_quantiles = noise_quantiles(base);
  base_noise_ = upload_noise(base);
  set_weather(weather::Weather{});
}

// Uploads the keyframes around utc_s (only those that changed) and sets the blend weight
// and the blended pole values.
void CloudRenderer::update_weather_textures(double utc_s) {
  const weather::WeatherTimeline::Blend b = timeline_.at(utc_s);
  const weather::WeatherMap* maps[2] = {b.from, b.to};
  const std::uint64_t versions[2] = {b.from_version, b.to_version};
  for (int k = 0; k < 2; ++k) {
    if (uploaded_version_[k] == versions[k] && weather_maps_[k]) continue;
    const weather::WeatherMap& m = *maps[k];
    if (!weather_maps_[k]) weather_maps_[k] = gl::make_texture_2d(GL_RGBA32F, m.width, m.height, GL_REPEAT, GL_CLAMP_TO_EDGE);
    glTextureSubImage2D(weather_maps_[k].id(), 0, 0, 0, m.width, m.height, GL_RGBA, GL_FLOAT, m.rgba.data());
    uploaded_version_[k] = versions[k];
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
}

void CloudRenderer::apply_tile(const weather::MapTile& tile, double now_utc_s) {
  const std::string problem = tile.problem();
  if (!problem.empty()) throw std::invalid_argument("weather tile: " + problem);
  timeline_.apply(tile, now_utc_s);
}

void CloudRenderer::set_weather(const weather::Weather& w) {
  const std::string problem = weather::validate(w);
  if (!problem.empty()) throw std::invalid_argument("invalid weather: " + problem);
  weather_ = w;
  wind_anchor_.reset();
  if (!map_valid_ || map_seed_ != w.map_seed) {
    timeline_.reset(weather::generate_procedural_map(w.map_seed, config_.weather_map_width, config_.weather_map_height));
    map_seed_ = w.map_seed;
    map_valid_ = true;
  }
}

void CloudRenderer::ensure_target(int w, int h) {
  if (target_ && w == target_w_ && h == target_h_) return;
  target_ = gl::make_texture_2d(GL_RGBA32F, w, h, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  target_w_ = w;
  target_h_ = h;
}

FrameImage CloudRenderer::render(const ViewRequest& view, const RenderQuality& quality) {
  if (view.width <= 0 || view.height <= 0) throw std::invalid_argument("render: empty image size");
  const auto start = std::chrono::steady_clock::now();
  ensure_target(view.width, view.height);

  if (!wind_anchor_) wind_anchor_ = WindAnchor{view.position, view.unix_time_s};
  update_weather_textures(view.unix_time_s);
  const FrameUniforms u = make_frame_uniforms(view, weather_, quality, facts_, &*wind_anchor_);
  glNamedBufferSubData(uniforms_.id(), 0, sizeof(FrameUniforms), &u);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, uniforms_.id());
  const Counters zero{0, 0, 0};
  glNamedBufferSubData(counters_.id(), 0, sizeof(Counters), &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counters_.id());

  const bool view_luts_recomputed = atmosphere_.update_view_dependent(u);

  scene_prog_.use();
  atmosphere_.bind_for_scene();
  glBindTextureUnit(3, base_noise_.id());
  glBindTextureUnit(4, detail_noise_.id());
  glBindTextureUnit(5, weather_maps_[0].id());
  glBindTextureUnit(9, weather_maps_[1].id());
  glBindImageTexture(0, target_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  dispatch_2d(view.width, view.height);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

  FrameImage img;
  img.width = view.width;
  img.height = view.height;
  img.rgba.resize(static_cast<size_t>(view.width) * view.height * 4);
  glGetTextureImage(target_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(img.rgba.size() * sizeof(float)),
                    img.rgba.data());
  Counters c{};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof(Counters), &c);
  const auto end = std::chrono::steady_clock::now();

  const geo::SolarPosition sp = geo::solar_position(view.unix_time_s, view.position.lat_deg, view.position.lon_deg);
  img.stats.view_luts_recomputed = view_luts_recomputed;
  img.stats.render_ms = std::chrono::duration<double, std::milli>(end - start).count();
  img.stats.sun_elevation_deg = sp.elevation_deg;
  img.stats.sun_azimuth_deg = sp.azimuth_deg;
  img.stats.cloud_pixels = c.cloud_pixels;
  img.stats.nonfinite_pixels = c.nonfinite_pixels;
  img.stats.density_evals_per_pixel =
      static_cast<double>(c.density_evals) / (static_cast<double>(view.width) * view.height);
  return img;
}

}  // namespace cloudsvc
