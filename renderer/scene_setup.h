// Per-frame constants for the GPU, computed on the CPU in double precision from the view
// and the weather: camera frame, osculating shell radius, sun direction,
// wrapped noise offsets. No GL here, so it is unit-testable.
#pragma once

#include "renderer/frame_uniforms.h"
#include "renderer/render_types.h"
#include "renderer/wind_drift.h"
#include <array>

#include "weather/cloud_layer.h"
#include "weather/noise_volumes.h"

namespace cloudsvc {

// Solar spectral irradiance at the top of the atmosphere at 680, 550, 440 nm
// (W m^-2 nm^-1; ASTM E-490 / the table of Bruneton's precomputed-scattering demo).
constexpr float kSolarIrradiance[3] = {1.474f, 1.8504f, 1.91198f};
constexpr double kSunAngularRadiusDeg = 0.2667;
// Diffuse albedo of the ground at 680/550/440 nm: a mix of vegetation and soil (land
// averages of ~0.15 in the red falling to ~0.08 in the blue).
constexpr float kGroundAlbedo[3] = {0.14f, 0.12f, 0.08f};
constexpr float kNightSkyRadiance = 2.0e-9f;    // W m^-2 sr^-1 nm^-1, airglow + starlight

// Values of a noise volume below which a fraction i / 15 of its texels lie (i = 0..15).
// The shader turns a layer's coverage c into the base-noise threshold Q(1 - c), so that
// coverage is the fraction of horizontal area covered by cloud at mid-profile.
using NoiseQuantiles = std::array<float, 16>;
NoiseQuantiles noise_quantiles(const weather::NoiseVolume& v);

// Facts about the GPU resources the frame constants refer to.
struct ResourceFacts {
  NoiseQuantiles base_quantiles{};      // of the base shape noise
  float detail_mean = 0.5f;             // mean value of the detail noise volume
  std::array<float, 4> weather_pole_south{0.5f, 0.5f, 0.5f, 0.0f};
  std::array<float, 4> weather_pole_north{0.5f, 0.5f, 0.5f, 0.0f};
  int weather_map_height = 1;
  float weather_blend = 0.0f;  // weight of the second weather keyframe (weather_timeline.h)
  bool coverage_pyramid = false;  // the coverage max-pyramid is bound (renderer/coverage_pyramid.h)
};

// wind_anchor: where/when the cloud field is undisplaced; nullptr anchors it at this view.
FrameUniforms make_frame_uniforms(const ViewRequest& view, const weather::Weather& weather,
                                  const RenderQuality& quality, const ResourceFacts& resources,
                                  const WindAnchor* wind_anchor = nullptr);

// Farthest distance (m) along a ray from altitude h at which anything below altitude H can
// still be seen over the horizon of a sphere of radius R: sqrt(h(2R+h)) + sqrt(H(2R+H)).
double horizon_reach_m(double R, double h, double H);

}  // namespace cloudsvc
