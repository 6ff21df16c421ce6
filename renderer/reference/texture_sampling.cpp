// GL texture sampling emulation (see texture_sampling.h).
#include "renderer/reference/texture_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace cloudsvc::reference {

namespace {

// Texel selection along one axis for GL_LINEAR (spec eq. 8.9-8.11): continuous texel
// coordinate x = u n - 1/2, lower index floor(x), weight of the upper texel frac(x).
struct AxisTexels {
  int i0 = 0, i1 = 0;
  double a = 0.0;  // weight of i1
};

AxisTexels repeat_axis(double u, int n) {
  // Reduce u to [0, 1) first so that the texel coordinate stays small (GL_REPEAT wraps
  // the integer indices; both give the same texels and weights). Then x is in
  // [-1/2, n - 1/2) and floor(x) in [-1, n - 1].
  double u01 = u - std::floor(u);
  if (u01 >= 1.0) u01 = 0.0;  // u just below an integer can round up to 1
  const double x = u01 * n - 0.5;
  const double fx = std::floor(x);
  AxisTexels t;
  t.a = x - fx;
  const int i = static_cast<int>(fx);
  t.i0 = i < 0 ? n - 1 : i;
  t.i1 = i + 1 >= n ? 0 : i + 1;
  return t;
}

AxisTexels clamp_axis(double v, int n) {
  const double x = v * n - 0.5;
  const double fx = std::floor(x);
  AxisTexels t;
  t.a = x - fx;
  const long long i = static_cast<long long>(std::clamp(fx, -2.0, static_cast<double>(n) + 1.0));
  t.i0 = static_cast<int>(std::clamp<long long>(i, 0, n - 1));
  t.i1 = static_cast<int>(std::clamp<long long>(i + 1, 0, n - 1));
  return t;
}

}  // namespace

double sample_r8_trilinear_repeat(const weather::NoiseVolume& volume, const glm::dvec3& uvw) {
  const int n = volume.size;
  const AxisTexels ax = repeat_axis(uvw.x, n), ay = repeat_axis(uvw.y, n), az = repeat_axis(uvw.z, n);
  const std::uint8_t* d = volume.data.data();
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  const std::size_t y0 = static_cast<std::size_t>(ay.i0) * n, y1 = static_cast<std::size_t>(ay.i1) * n;
  const std::size_t z0 = static_cast<std::size_t>(az.i0) * nn, z1 = static_cast<std::size_t>(az.i1) * nn;
  // Bilinear in x-y on one z slice, from the four bytes of the cell.
  const auto slice = [&](std::size_t z) {
    const double c0 = d[z + y0 + ax.i0] + ax.a * (static_cast<double>(d[z + y0 + ax.i1]) - d[z + y0 + ax.i0]);
    const double c1 = d[z + y1 + ax.i0] + ax.a * (static_cast<double>(d[z + y1 + ax.i1]) - d[z + y1 + ax.i0]);
    return c0 + ay.a * (c1 - c0);
  };
  const double s0 = slice(z0), s1 = slice(z1);
  return (s0 + az.a * (s1 - s0)) / 255.0;  // R8 unsigned normalised: byte / 255
}

glm::dvec4 sample_rgba32f_bilinear_repeat_clamp(const weather::WeatherMap& map, double u, double v) {
  const AxisTexels ax = repeat_axis(u, map.width);
  const AxisTexels ay = clamp_axis(v, map.height);
  const auto texel = [&](int i, int j) {
    const float* t = &map.rgba[(static_cast<std::size_t>(j) * map.width + i) * 4];
    return glm::dvec4(t[0], t[1], t[2], t[3]);
  };
  const glm::dvec4 south = glm::mix(texel(ax.i0, ay.i0), texel(ax.i1, ay.i0), ax.a);
  const glm::dvec4 north = glm::mix(texel(ax.i0, ay.i1), texel(ax.i1, ay.i1), ax.a);
  return glm::mix(south, north, ay.a);
}

glm::dvec4 weather_map_pole_value(const weather::WeatherMap& map, bool north) {
  glm::dvec4 sum(0.0);
  const int j = north ? map.height - 1 : 0;
  for (int i = 0; i < map.width; ++i) {
    const float* t = &map.rgba[(static_cast<std::size_t>(j) * map.width + i) * 4];
    sum += glm::dvec4(t[0], t[1], t[2], t[3]);
  }
  return sum / static_cast<double>(map.width);
}

glm::dvec4 sample_weather_map(const weather::WeatherMap& map, const glm::dvec4& pole_south,
                              const glm::dvec4& pole_north, double lat_rad, double lon_rad) {
  constexpr double kPi = std::numbers::pi;
  const double u = lon_rad / (2.0 * kPi) + 0.5;
  const double v = lat_rad / kPi + 0.5;
  glm::dvec4 w = sample_rgba32f_bilinear_repeat_clamp(map, u, v);
  const double y = v * map.height - 0.5;  // continuous row coordinate
  const double last = map.height - 1.0;
  if (y < 0.0) w = glm::mix(w, pole_south, std::min(1.0, -2.0 * y));
  else if (y > last) w = glm::mix(w, pole_north, std::min(1.0, 2.0 * (y - last)));
  return w;
}

Quantiles16 value_quantiles(const weather::NoiseVolume& volume) {
  std::vector<std::uint8_t> values(volume.data.begin(), volume.data.end());
  const double n = static_cast<double>(values.size());
  Quantiles16 q{};
  for (int i = 1; i < 15; ++i) {
    // smallest v with #(x <= v) >= n i / 15: the element of rank ceil(n i / 15) - 1
    const double target = n * i / 15.0;
    const auto rank = static_cast<std::ptrdiff_t>(std::max(0.0, std::ceil(target) - 1.0));
    std::nth_element(values.begin(), values.begin() + rank, values.end());
    q[static_cast<std::size_t>(i)] = values[static_cast<std::size_t>(rank)] / 255.0;
  }
  q[0] = 0.0;
  q[15] = 1.0;
  return q;
}

double interpolate_quantile(const Quantiles16& q, double p) {
  const double x = std::clamp(p, 0.0, 1.0) * 15.0;
  const int i = std::min(static_cast<int>(x), 14);
  return q[static_cast<std::size_t>(i)] + (x - i) * (q[static_cast<std::size_t>(i) + 1] - q[static_cast<std::size_t>(i)]);
}

}  // namespace cloudsvc::reference
