// One frame's state in double precision, built once per frame (make_frame_context) from
// the view, the weather and the wind anchor, and read by every CPU step of the frame:
// layer culling, ray classification (renderer/layers_in_view.h), LUT planning
// (renderer/atmosphere_luts.h), the ground shadow map, temporal reprojection and the
// frame statistics. Packing the GPU uniforms (renderer/frame_uniforms_packing.h) is the
// last step and writes only. No GL here.
// Frames: "local" = East-North-Up axes at the camera, origin at the camera, metres;
// ECEF = WGS84 Earth-centred, Earth-fixed, metres.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "geodesy/geodetic.h"
#include "geodesy/solar_position.h"
#include "renderer/gpu_interface.h"
#include "renderer/api/view_request.h"
#include "weather/wind_drift.h"
#include "weather/cloud_layer.h"

namespace cloudsvc {

// One cloud layer as this frame draws it.
struct LayerFrame {
  weather::CloudLayer layer;                   // as set (base, top, coverage, type, ...)
  // Rotation taking an ECEF position to the wind-rotated cloud field (wind_rotation).
  glm::dmat3 field_rotation{1.0};
  // The shape noise's east-west strands, S of weather/noise_shaping.h (field frame;
  // the identity but for cirrus).
  glm::dmat3 noise_shaping{1.0};
  // The camera's position in the layer's noise space: S times the field-rotated ECEF
  // position with altitude stretched by the type's noise vertical scale k,
  // f(X) = X + (k - 1) a(X) n(X).
  glm::dvec3 camera_field_m{0.0};
  double base_period_m = 1.0;    // period of the base-shape noise (m)
  double detail_period_m = 1.0;  // ... of the detail noise (base / 8)
  // No cloud of this layer anywhere the frame can reach (CloudRenderer culling,
  // renderer/coverage_cull.h): not marched, coverage 0 on the GPU.
  bool culled = false;
  // Drawn as individual cumulus domes (weather/cumulus_domes.h; RendererConfig::cumulus_domes).
  bool domes = false;

  // Coverage the march uses: 0 for a culled layer.
  double drawn_coverage() const { return culled ? 0.0 : layer.coverage; }
};

// The aerial-perspective volume's frustum (AtmosphereLuts::plan_view_dependent): local ENU
// axes and the tangents of its half width and height.
struct ApFrustum {
  glm::dvec3 forward{0.0, 1.0, 0.0}, right{1.0, 0.0, 0.0}, up{0.0, 0.0, 1.0};
  double tan_half_width = 1.0, tan_half_height = 1.0;
};

struct FrameContext {
  ViewRequest view;
  glm::dvec3 camera_ecef{0.0};
  glm::dmat3 enu_to_ecef{1.0};  // columns: local east, north, up in ECEF
  geo::BodyAxes axes;           // camera forward, right, up (local ENU)
  ImageWindow window;  // image_window(view): the tangents of the image's centre and half extents
  // Cloud shell and ground: spheres of radius shell_radius_m (the osculating sphere of
  // WGS84 at the camera) centred at (0, 0, -(R + camera_altitude_m)) in the local frame.
  double shell_radius_m = 0.0;
  double camera_altitude_m = 0.0;
  double ground_altitude_m = 0.0;  // 0, or just below a camera below the ellipsoid
  double march_reach_m = 0.0;      // farthest cloud any ray can see (horizon_reach_m)
  geo::SolarPosition sun;          // at the camera, at the view's time
  glm::dvec3 sun_enu{0.0, 0.0, 1.0};   // unit vector to the sun, local ENU
  glm::dvec3 sun_ecef{0.0, 0.0, 1.0};  // ... in ECEF axes
  glm::dvec3 ground_albedo{0.0};       // Lambertian, rgb (model::ground_albedo_rgb of the weather)
  // Factor on the atmosphere's aerosol (model::atmosphere::aerosol_scale_of the weather's
  // visibility; 1 = the model's own haze).
  double aerosol_scale = 1.0;
  int layer_count = 0;                 // layers drawn: min(weather layers, gpu::kMaxLayers)
  std::array<LayerFrame, gpu::kMaxLayers> layers{};
  ApFrustum ap;  // set by AtmosphereLuts::plan_view_dependent

  unsigned culled_mask() const;  // bit i: layer i culled
  // Depth of the aerial-perspective volume: the farthest visible ground or cloud (hundreds
  // of km), at least 1 km.
  double ap_max_distance_m() const { return march_reach_m > 1000.0 ? march_reach_m : 1000.0; }
};

// Builds the context of `view` (the layers not culled; the AP frustum the camera's).
FrameContext make_frame_context(const ViewRequest& view, const weather::Weather& weather, const WindAnchor& anchor);

// Farthest distance (m) along a ray from altitude h at which anything below altitude H can
// still be seen over the horizon of a sphere of radius R: sqrt(h(2R+h)) + sqrt(H(2R+H)).
double horizon_reach_m(double R, double h, double H);

}  // namespace cloudsvc
