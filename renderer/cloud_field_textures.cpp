#include "renderer/cloud_field_textures.h"

#include <algorithm>
#include <cmath>

#include "renderer/coverage_pyramid.h"
#include "renderer/gpu_interface.h"
#include "weather/noise_max_pyramid.h"
#include "weather/noise_volumes.h"

namespace cloudsvc {

namespace {

gl::Texture upload_noise(const weather::NoiseVolume& v) {
  gl::Texture t = gl::make_texture_3d(GL_R8, v.size, v.size, v.size, GL_REPEAT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage3D(t.id(), 0, 0, 0, 0, v.size, v.size, v.size, GL_RED, GL_UNSIGNED_BYTE, v.data.data());
  return t;
}

// The max pyramid's levels as the mip levels of one texture, read texel by texel
// (texelFetch; no filtering).
gl::Texture upload_max_pyramid(const weather::NoiseMaxPyramid& p) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &id);
  glTextureStorage3D(id, p.level_count(), GL_R8, p.size(), p.size(), p.size());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int l = 0; l < p.level_count(); ++l) {
    const int n = p.size() >> l;
    glTextureSubImage3D(id, l, 0, 0, 0, n, n, n, GL_RED, GL_UNSIGNED_BYTE, p.level(l).data());
  }
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return gl::Texture(id);
}

}  // namespace

CloudFieldTextures::CloudFieldTextures(const RendererConfig& config) : config_(config) {
  const weather::NoiseVolume base = weather::make_base_shape_noise(config.base_noise_size, config.noise_seed);
  summary_.base_quantiles = noise_quantiles(base);
  summary_.base_mean = static_cast<float>(weather::noise_mean(base));
  summary_.noise_seed = config.noise_seed;
  base_noise_ = upload_noise(base);
  const weather::NoiseMaxPyramid base_max(base);
  base_noise_max_ = upload_max_pyramid(base_max);
  for (int l = 0; l < base_max.level_count(); ++l) noise_bytes_ += base_max.level(l).size();
  const weather::NoiseVolume detail = weather::make_detail_noise(config.detail_noise_size, config.noise_seed + 1);
  summary_.detail_mean = static_cast<float>(weather::noise_mean(detail));
  detail_noise_ = upload_noise(detail);
  noise_bytes_ += base.data.size() + detail.data.size();
}

std::size_t CloudFieldTextures::gpu_bytes() const {
  std::size_t layer_bytes = 0;
  for (int k = 0; k < 2; ++k)
    layer_bytes += layer_maps_full_[k] ? static_cast<std::size_t>(config_.weather_map_width) * config_.weather_map_height * 16 : 16;
  return noise_bytes_ + 2 * static_cast<std::size_t>(config_.weather_map_width) * config_.weather_map_height * 16 +
         layer_bytes + coverage_pyramid_bytes_;
}

bool CloudFieldTextures::update(const weather::WeatherTimeline::Blend& b) {
  const weather::WeatherMap* maps[2] = {b.from, b.to};
  bool changed = false;
  bool pyramid_stale = !coverage_pyramid_;
  const std::uint64_t versions[2] = {b.from_version, b.to_version};
  for (int k = 0; k < 2; ++k) {
    if (uploaded_version_[k] == versions[k] && weather_maps_[k]) continue;
    const weather::WeatherMap& m = *maps[k];
    if (!weather_maps_[k]) weather_maps_[k] = gl::make_texture_2d(GL_RGBA32F, m.width, m.height, GL_REPEAT, GL_CLAMP_TO_EDGE);
    glTextureSubImage2D(weather_maps_[k].id(), 0, 0, 0, m.width, m.height, GL_RGBA, GL_FLOAT, m.rgba.data());
    const bool full = m.has_layer_coverage();
    if (!layer_maps_[k] || layer_maps_full_[k] != full)
      layer_maps_[k] = gl::make_texture_2d(GL_RGBA32F, full ? m.width : 1, full ? m.height : 1, GL_REPEAT, GL_CLAMP_TO_EDGE);
    const float zeros[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glTextureSubImage2D(layer_maps_[k].id(), 0, 0, 0, full ? m.width : 1, full ? m.height : 1, GL_RGBA, GL_FLOAT,
                        full ? m.layer_coverage.data() : zeros);
    layer_maps_full_[k] = full;
    uploaded_version_[k] = versions[k];
    changed = true;
    pyramid_stale = true;
  }
  if (pyramid_stale) upload_coverage_pyramid(*b.from, b.to != b.from ? b.to : nullptr);
  // a fading keyframe changes the clouds slowly: count steps of 2 % of the blend
  if (std::abs(b.weight - uploaded_blend_) > 0.02f) {
    uploaded_blend_ = static_cast<float>(b.weight);
    changed = true;
  }
  float south[2][4], north[2][4];
  for (int k = 0; k < 2; ++k) {
    maps[k]->pole_value(false, south[k]);
    maps[k]->pole_value(true, north[k]);
  }
  float layer_south[2][4], layer_north[2][4];
  for (int k = 0; k < 2; ++k) {
    maps[k]->layer_coverage_pole_value(false, layer_south[k]);
    maps[k]->layer_coverage_pole_value(true, layer_north[k]);
  }
  const auto mix = [&](const float (&v)[2][4], int i) { return v[0][i] + b.weight * (v[1][i] - v[0][i]); };
  for (int i = 0; i < 4; ++i) {
    const auto c = static_cast<size_t>(i);
    summary_.weather_pole_south[c] = mix(south, i);
    summary_.weather_pole_north[c] = mix(north, i);
    summary_.layer_coverage_pole_south[c] = mix(layer_south, i);
    summary_.layer_coverage_pole_north[c] = mix(layer_north, i);
  }
  summary_.weather_map_height = b.from->height;
  summary_.weather_blend = b.weight;
  return changed;
}

// The coverage max-pyramid of the keyframes (renderer/coverage_pyramid.h) into the storage
// buffer shaders/coverage_pyramid.glsl reads; off (the march does not query it) for a map
// too large to pack.
void CloudFieldTextures::upload_coverage_pyramid(const weather::WeatherMap& from, const weather::WeatherMap* to) {
  const std::vector<std::uint32_t> words = pack_for_gpu(build_coverage_pyramid(from, to));
  summary_.coverage_pyramid = !words.empty();
  // off: a buffer of the block's fixed part and one cell (bound, never read: the frame
  // uniforms' coverage_pyramid is 0)
  const std::size_t bytes = std::max<std::size_t>(words.size(), 4 * kGpuPyramidLevels + 1) * sizeof(std::uint32_t);
  if (!coverage_pyramid_ || bytes != coverage_pyramid_bytes_) {
    coverage_pyramid_ = gl::make_buffer(static_cast<GLsizeiptr>(bytes), nullptr, GL_STATIC_DRAW);
    coverage_pyramid_bytes_ = bytes;
  }
  if (!words.empty()) glNamedBufferSubData(coverage_pyramid_.id(), 0, static_cast<GLsizeiptr>(bytes), words.data());
}

void CloudFieldTextures::bind() const {
  glBindTextureUnit(gpu::tex::BASE_NOISE, base_noise_.id());
  glBindTextureUnit(gpu::tex::BASE_NOISE_MAX, base_noise_max_.id());
  glBindTextureUnit(gpu::tex::DETAIL_NOISE, detail_noise_.id());
  glBindTextureUnit(gpu::tex::WEATHER_MAP, weather_maps_[0].id());
  glBindTextureUnit(gpu::tex::WEATHER_MAP_NEXT, weather_maps_[1].id());
  glBindTextureUnit(gpu::tex::LAYER_COVERAGE, layer_maps_[0].id());
  glBindTextureUnit(gpu::tex::LAYER_COVERAGE_NEXT, layer_maps_[1].id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::COVERAGE_PYRAMID, coverage_pyramid_.id());
}

}  // namespace cloudsvc
