// Everything the reference needs to know about one view, derived in double precision
// from the ViewRequest and the Weather with the geodesy and model libraries, independently
// of the GPU path's renderer/frame_context.cpp:
//   - frames: "local" = East-North-Up axes at the camera, origin at the camera, metres;
//     "ECEF" = WGS84 Earth-centred, Earth-fixed axes;
//   - the cloud shell and the ground: spheres of the osculating radius R = sqrt(M N) at the
//     camera's latitude, centred at (0, 0, -(R + h)) in the local frame, h = camera
//     altitude above the ellipsoid; ground at altitude min(0, h - 1 m);
//   - the sun: NOAA solar position (geo::solar_position), geometric elevation, as a unit
//     vector in the local frame (the same for every point: the sun is at infinity);
//   - per cloud layer: altitudes, coverage, extinction from droplet microphysics, phase
//     parameters, noise periods and the wind rotation of its field.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "geodesy/geodetic.h"
#include "renderer/model/mie_phase_table.h"
#include "renderer/model/phase_function.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"
#include "weather/wind_drift.h"  // WindAnchor (plain struct; wind_rotation() itself is not used)
#include "weather/cloud_layer.h"

namespace cloudsvc::reference {

// Rotation R (ECEF -> ECEF) such that the layer's noise field is sampled at R x for an
// ECEF point x at time t. A wind v (east, north, m/s) at the anchor point P moves the field
// as a solid body about the axis k = (P x v) / |P x v| with angular speed |v| / |P|; the
// field has turned by angle = w (t - t0) (wrapped into [-pi, pi]) and is sampled at the
// inverse rotation: R = Rodrigues(k, -angle). Calm or degenerate wind: identity.
// Written here in double from that definition (the GPU path has its own implementation in
// renderer/wind_drift.cpp; the accuracy test compares the two).
glm::dmat3 field_rotation(const weather::Wind& wind, const WindAnchor& anchor, double unix_time_s);

// Pinhole camera: ray through normalised device coordinates (ndc_x, ndc_y) in [-1, 1]
// (y up) is normalise(forward + ndc_x tan(hfov/2) right + ndc_y tan(vfov/2) up), local frame.
struct ReferenceCamera {
  glm::dvec3 forward{0, 1, 0}, right{1, 0, 0}, up{0, 0, 1};
  ImageWindow window;  // image_window(view): tangents of the image's centre and half extents
  int width = 0, height = 0;
  double near_m = 0.0, far_m = 0.0;  // ViewRequest's planes: clouds drawn between them (cloud_clip)

  // Ray through the point (px, py) of the image in pixel units from its top-left corner
  // (the centre of pixel (x, y) is (x + 0.5, y + 0.5)).
  glm::dvec3 ray_at(double px, double py) const;
};

struct ShellFrame {
  double radius_m = 0.0;         // R, osculating sphere radius at the camera latitude
  double camera_alt_m = 0.0;     // h, above the ellipsoid (= above the shell sphere at the camera)
  double ground_alt_m = 0.0;     // min(0, h - 1)
  glm::dmat3 enu_to_ecef{1.0};   // columns: east, north, up at the camera, ECEF axes
  glm::dvec3 camera_ecef{0.0};   // m

  // Altitude above the shell sphere of a local point p: |p + (0, 0, R + h)| - R. In double
  // the cancellation costs ~1e-9 m, so the direct form is used.
  double altitude_of(const glm::dvec3& p) const;
  // Unit vector away from the shell centre at p (local frame).
  glm::dvec3 up_at(const glm::dvec3& p) const;
};

struct ReferenceLayer {
  double base_m = 0.0, top_m = 0.0;   // altitudes above the shell sphere (= ellipsoid at the camera)
  double coverage = 0.0;              // layer coverage c, [0, 1]
  double density_scale = 1.0;         // multiplier of the microphysical extinction
  double sigma_max_per_m = 0.0;       // N0 Q_ext pi (d/2)^2, model::cloud_extinction_per_m, 1/m
  model::JdDParams phase;             // Jendersie-d'Eon parameters for the droplet diameter
  // The droplets' tabulated Mie phase function (model::mie_phase_table), where the scene
  // scatters with it (model::CloudPhaseModel::kMie); null: the fit above.
  std::shared_ptr<const model::PhaseTable> mie_phase;
  double base_period_m = 8000.0;      // horizontal period of the base shape noise (type trait)
  double detail_period_m = 1000.0;    // base_period / 8
  double erosion = 0.5;               // detail erosion strength (type trait base_erosion)
  double bottom_ramp = 0.1, top_ramp = 0.3, top_weight = 0.0;  // height profile (type traits)
  double noise_vertical_scale = 1.0;  // k: the noise is sampled at X + (k - 1) a(X) n(X) (type trait)
  bool stratiform = false;
  double base_relief = 0.0;           // fraction of the depth the base rises by (type trait base_relief)
  weather::Anvil anvil;               // the type's anvil (spread 0: none)
  weather::CloudType type = weather::CloudType::Cumulus;
  std::uint32_t dome_seed = 0;        // weather::dome_placement_seed (cumulus domes)
  // The noise field coordinate (m, ECEF axes of the wind-rotated field) of a local point p
  // at altitude a with up vector n (shell frame) is
  //   camera_field + field_from_local * (p + (k - 1) a n),
  // i.e. R * (X + (k - 1) a n) for the ECEF point X: divide by a period for texture coordinates.
  glm::dmat3 field_from_local{1.0};   // field rotation * enu_to_ecef
  glm::dvec3 camera_field{0.0};       // field rotation * camera ECEF, m
  // The shape noise is read at noise_shaping * field point (weather/noise_shaping.h:
  // east-west strands; the identity but for cirrus).
  glm::dmat3 noise_shaping{1.0};
};

struct ReferenceScene {
  ReferenceCamera camera;
  ShellFrame shell;
  glm::dvec3 sun_local{0, 0, 1};    // unit vector towards the sun, local frame
  double sun_elevation_deg = 0.0;   // geometric, at the camera
  double sun_azimuth_deg = 0.0;
  std::vector<ReferenceLayer> layers;  // at most kMaxCloudLayers, in the weather's order
  glm::dvec3 ground_albedo{0.0};       // Lambertian, rgb (model::ground_albedo_rgb of the weather)
  double aerosol_scale = 1.0;          // the air's aerosol (model::atmosphere::aerosol_scale_of the visibility)
};

// anchor: nullptr anchors every layer's field at this view (no displacement), as
// CloudRenderer does for the first view after set_weather.
// phase: which phase function the layers scatter with (Mie: their tables are computed on
// first use of a droplet size, model::mie_phase_table).
ReferenceScene make_reference_scene(const ViewRequest& view, const weather::Weather& weather,
                                    const WindAnchor* anchor = nullptr,
                                    model::CloudPhaseModel phase = model::CloudPhaseModel::kFit);

}  // namespace cloudsvc::reference
