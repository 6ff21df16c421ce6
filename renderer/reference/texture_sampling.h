// Emulation, in double precision, of the OpenGL texture fetches the cloud model depends
// on (OpenGL 4.6 core spec §8.14 "Texture minification", §8.14.2 "Coordinate wrapping and
// texel selection", eqs. 8.8-8.11): level 0 only (the shaders use textureLod(..., 0)),
// GL_LINEAR filtering, texel centres at (i + 0.5) / n. The weights are exact (double);
// a GPU may quantise them (llvmpipe uses 8 bits of sub-texel precision for 8-bit formats),
// which is one source of small, expected differences.
//
// This is reference code: it shares nothing with the shaders or the GL upload code, only
// the data (weather::NoiseVolume, weather::WeatherMap) produced by the weather module.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "weather/noise_volumes.h"
#include "weather/weather_map.h"

namespace cloudsvc::reference {

// GL_LINEAR + GL_REPEAT on all three axes of an R8 (unsigned normalised) 3D texture:
// for each axis i0 = floor(u n - 1/2), weight a = frac(u n - 1/2), indices taken modulo n;
// texel value = byte / 255. uvw in texture units (1 = one period), any magnitude.
double sample_r8_trilinear_repeat(const weather::NoiseVolume& volume, const glm::dvec3& uvw);

// GL_LINEAR on an RGBA32F 2D texture with GL_REPEAT in s (u, longitude) and
// GL_CLAMP_TO_EDGE in t (v, latitude): i = floor(u W - 1/2) mod W, j clamped to [0, H - 1].
// Row 0 of the map is t = 0 (the southernmost row), as glTextureSubImage2D uploads it.
glm::dvec4 sample_rgba32f_bilinear_repeat_clamp(const weather::WeatherMap& map, double u, double v);

// The value the weather map takes at a pole: the mean of its outermost row (south: row 0).
glm::dvec4 weather_map_pole_value(const weather::WeatherMap& map, bool north);

// The weather lookup of the cloud model at a direction with latitude lat_rad and
// longitude lon_rad (from the shell centre, ECEF axes): bilinear texture value at
// u = lon / 2pi + 1/2, v = lat / pi + 1/2, then, within half a texel row of a pole
// (y = v H - 1/2 < 0 or > H - 1), a linear blend towards the pole value with weight
// min(1, 2 |y overshoot|), so that every longitude meets at the same value.
glm::dvec4 sample_weather_map(const weather::WeatherMap& map, const glm::dvec4& pole_south,
                              const glm::dvec4& pole_north, double lat_rad, double lon_rad);

// Values below which a fraction i / 15 (i = 0..15) of the volume's texels lie: the
// smallest stored value v with #(texels <= v) >= N i / 15, with q[0] = 0 and q[15] = 1 by
// definition (the coverage threshold Q(1 - c) then removes everything at c = 0 and
// nothing at c = 1). Computed here by selection (std::nth_element) on a copy.
using Quantiles16 = std::array<double, 16>;
Quantiles16 value_quantiles(const weather::NoiseVolume& volume);

// Piecewise-linear interpolation of the 16 quantiles at a fraction p (clamped to [0, 1]).
double interpolate_quantile(const Quantiles16& q, double p);

}  // namespace cloudsvc::reference
