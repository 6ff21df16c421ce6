// Global weather map: procedural generation on the sphere and bilinear sampling.
// See weather_map.h and docs/WEATHER.md.
//
// Each channel is fBm Perlin noise (4 octaves, gain 0.5) evaluated at the texel centre's
// position on a sphere of radius R / feature_km lattice cells (R = 6371 km, the mean
// Earth radius): the lowest octave's lattice spacing is feature_km along the surface.
// Because the noise lives in 3D, longitudes -180 and +180 are the same point (no seam)
// and texels near a pole sample a small circle around it (no pinching or streaks).
// Channel value = clamp(0.5 + gain * fbm, 0, 1); the fBm's standard deviation is about
// 0.17, so gain 1.25 gives R and G a standard deviation of about 0.2 around 0.5
// (clamping affects ~1 % of texels) and gain 1.0 gives B about 0.17.
#include "weather/weather_map.h"

#include <algorithm>
#include <cmath>

#include "common/parallel_for.h"
#include "weather/gradient_noise.h"
#include "weather/noise_hash.h"

namespace cloudsvc::weather {
namespace {

constexpr double kEarthRadius_km = 6371.0;  // mean radius (IUGG)
constexpr double kPi = 3.14159265358979323846;
constexpr int kOctaves = 4;

struct ChannelNoise {
  detail::PerlinFbm fbm;
  double gain;
};

// Neutral value returned for positions or maps that cannot be sampled.
constexpr float kNeutral[4] = {0.5f, 0.5f, 0.5f, 0.0f};

}  // namespace

WeatherMap generate_procedural_map(std::uint32_t seed, int width, int height,
                                   double feature_km) {
  WeatherMap map;
  if (width <= 0 || height <= 0) return map;
  map.width = width;
  map.height = height;
  map.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0.0f);
  if (!(feature_km > 0.0) || !std::isfinite(feature_km)) feature_km = 300.0;
  const double radius_cells = kEarthRadius_km / feature_km;
  const ChannelNoise channels[3] = {
      {detail::PerlinFbm(kOctaves, 0, detail::sub_seed(seed, 1)), 1.25},   // R coverage
      {detail::PerlinFbm(kOctaves, 0, detail::sub_seed(seed, 2)), 1.25},   // G cloud type
      {detail::PerlinFbm(kOctaves, 0, detail::sub_seed(seed, 3)), 1.0}};   // B density

  // Unit vectors of the texel-centre longitudes, shared by all rows.
  std::vector<double> cos_lon(width), sin_lon(width);
  for (int i = 0; i < width; ++i) {
    const double lon = (-180.0 + (i + 0.5) * 360.0 / width) * kPi / 180.0;
    cos_lon[i] = std::cos(lon);
    sin_lon[i] = std::sin(lon);
  }

  parallel_for(height, kAllThreads, [&](int j) {
    const double lat = (-90.0 + (j + 0.5) * 180.0 / height) * kPi / 180.0;
    const double r_xy = radius_cells * std::cos(lat);
    const double z = radius_cells * std::sin(lat);
    float* row = &map.rgba[static_cast<std::size_t>(j) * width * 4];
    for (int i = 0; i < width; ++i) {
      const double x = r_xy * cos_lon[i], y = r_xy * sin_lon[i];
      for (int c = 0; c < 3; ++c) {
        const double n = channels[c].fbm(x, y, z);
        row[4 * i + c] = static_cast<float>(std::clamp(0.5 + channels[c].gain * n, 0.0, 1.0));
      }
      row[4 * i + 3] = 0.0f;  // A: reserved (precipitation)
    }
  });
  return map;
}

namespace {

// Mean of the southernmost or northernmost row of a 4-channel grid; `fallback` for an empty one.
void grid_pole_value(const std::vector<float>& data, int width, int height, bool north, const float fallback[4],
                     float out[4]) {
  double mean[4] = {0, 0, 0, 0};
  const bool usable = width > 0 && height > 0 && data.size() >= static_cast<std::size_t>(width) * height * 4;
  if (usable) {
    const float* row = &data[static_cast<std::size_t>(north ? height - 1 : 0) * width * 4];
    for (int i = 0; i < width; ++i)
      for (int k = 0; k < 4; ++k) mean[k] += row[4 * i + k];
  }
  for (int k = 0; k < 4; ++k) out[k] = usable ? static_cast<float>(mean[k] / width) : fallback[k];
}

// Bilinear sample of a 4-channel grid of the map's texels (see WeatherMap::sample).
void sample_grid(const std::vector<float>& data, int width, int height, double lat_deg, double lon_deg,
                 const float fallback[4], float out[4]) {
  const bool usable = width > 0 && height > 0 && data.size() >= static_cast<std::size_t>(width) * height * 4 &&
                      std::isfinite(lat_deg) && std::isfinite(lon_deg);
  if (!usable) {
    std::copy(fallback, fallback + 4, out);
    return;
  }
  // Longitude into [0, 360) from -180 first (exact for |lon| < 2^53), then to texel-centre
  // coordinates x in [-0.5, width - 0.5), wrapped into [0, width).
  double lon = std::fmod(lon_deg + 180.0, 360.0);
  if (lon < 0.0) lon += 360.0;
  double x = lon / 360.0 * width - 0.5;
  if (x < 0.0) x += width;
  const double fx = std::floor(x);
  int i0 = static_cast<int>(fx);
  if (i0 >= width) i0 -= width;  // x rounded up to width
  const int i1 = (i0 + 1 == width) ? 0 : i0 + 1;
  const double tx = x - fx;

  const auto texel = [&](int i, int j) { return &data[(static_cast<std::size_t>(j) * width + i) * 4]; };
  // Bilinear in longitude along row j.
  const auto along_row = [&](int j, int k) {
    const float a = texel(i0, j)[k], b = texel(i1, j)[k];
    return a + tx * (b - a);
  };

  const double y = (std::clamp(lat_deg, -90.0, 90.0) + 90.0) / 180.0 * height - 0.5;
  if (y >= 0.0 && y <= height - 1.0) {
    const int j0 = std::min(static_cast<int>(y), height - 1);
    const int j1 = std::min(j0 + 1, height - 1);
    const double ty = y - j0;
    for (int k = 0; k < 4; ++k) {
      const double south = along_row(j0, k), north = along_row(j1, k);
      out[k] = static_cast<float>(south + ty * (north - south));
    }
    return;
  }
  // Polar cap: y in [-0.5, 0) (south) or (height - 1, height - 0.5] (north).
  const int j = y < 0.0 ? 0 : height - 1;
  const double t = std::min(1.0, 2.0 * (y < 0.0 ? -y : y - (height - 1.0)));
  float pole[4];
  grid_pole_value(data, width, height, j != 0, fallback, pole);
  for (int k = 0; k < 4; ++k) {
    const double ring = along_row(j, k);
    out[k] = static_cast<float>(ring + t * (pole[k] - ring));
  }
}

constexpr float kNoCoverage[4] = {0.0f, 0.0f, 0.0f, 0.0f};

}  // namespace

void WeatherMap::sample(double lat_deg, double lon_deg, float out[4]) const {
  sample_grid(rgba, width, height, lat_deg, lon_deg, kNeutral, out);
}

void WeatherMap::pole_value(bool north, float out[4]) const { grid_pole_value(rgba, width, height, north, kNeutral, out); }

void WeatherMap::sample_layer_coverage(double lat_deg, double lon_deg, float out[4]) const {
  if (!has_layer_coverage()) {
    std::copy(kNoCoverage, kNoCoverage + 4, out);
    return;
  }
  sample_grid(layer_coverage, width, height, lat_deg, lon_deg, kNoCoverage, out);
}

void WeatherMap::layer_coverage_pole_value(bool north, float out[4]) const {
  if (!has_layer_coverage()) {
    std::copy(kNoCoverage, kNoCoverage + 4, out);
    return;
  }
  grid_pole_value(layer_coverage, width, height, north, kNoCoverage, out);
}

float WeatherMap::coverage_bound(std::size_t n) const {
  const auto bound = [](float v, float m) { return !(v <= m) ? (std::isfinite(v) ? v : 1.0f) : m; };
  float m = bound(rgba[4 * n], 0.0f);
  if (has_layer_coverage())
    for (int k = 0; k < 4; ++k) m = bound(layer_coverage[4 * n + k], m);
  return m;
}

namespace {

template <typename T>
T modulated_layer_coverage(T layer_coverage, T m) {
  if (!std::isfinite(layer_coverage)) return T(0);
  const T c = std::clamp(layer_coverage, T(0), T(1));
  if (!std::isfinite(m)) m = T(0.5);
  return std::clamp(c + T(1.2) * std::min(c, T(1) - c) * (T(2) * m - T(1)), T(0), T(1));
}

}  // namespace

float local_coverage(float layer_coverage, float m) { return modulated_layer_coverage(layer_coverage, m); }
float layer_local_coverage(int channel, float layer_coverage, float value) {
  if (channel < 0) return local_coverage(layer_coverage, value);
  return std::isfinite(value) ? std::clamp(value, 0.0f, 1.0f) : 0.0f;
}
double local_coverage(double layer_coverage, double m) { return modulated_layer_coverage(layer_coverage, m); }

}  // namespace cloudsvc::weather
