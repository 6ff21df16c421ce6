// CPU reference renderer (docs/ACCURACY.md §1, docs/REFERENCE.md): the same physical model as the
// GPU renderer (docs/RENDERING.md), evaluated independently in double precision at
// converged settings. It shares only the inputs with the GPU path (weather module data,
// geodesy, model constants and the model's CPU twins in renderer/model/); every line of
// evaluation code (camera, shell geometry, texture sampling, density, light, atmosphere)
// is its own. See docs/REFERENCE.md for what it can and cannot catch and its convergence.
//
// Per pixel (ray through the pixel centre, no jitter; or the mean of pixel_samples^2 rays
// through the centres of a pixel_samples x pixel_samples grid of sub-pixels: the box-filtered
// pixel footprint):
//   clouds: march every layer interval with steps of cloud_step_m (scaled per layer,
//     cloud_lighting.h) until the cloud transmittance falls below min_transmittance;
//     at each sample with sigma_t > 0: sun = E_sun T_atm sum_i b^i p_i e^{-a^i tau} with tau
//     from a light march with light_step_m steps (4 km cap), plus the diffuse term (Monte
//     Carlo source tables); energy-conserving accumulation (Hillaire 2016, albedo 1).
//   background: sky (single scattering integrated along the ray + Psi_ms, sun disk, night
//     sky radiance) or ground (Lambertian, sun through a fine shadow march of every layer,
//     sky irradiance, aerial perspective integrated along the ray to the ground).
//   aerial perspective on the clouds: integrated along the ray to the transmittance-
//     weighted mean cloud depth (the model's definition).
#pragma once

#include "renderer/reference/atmosphere_tables.h"
#include "renderer/reference/reference_inputs.h"
#include "renderer/model/mie_phase_table.h"
#include "renderer/model/scene_constants.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"
#include "weather/wind_drift.h"  // WindAnchor (plain struct)
#include "weather/cloud_layer.h"

namespace cloudsvc::reference {

// Revision of the light model the reference (and the GPU) computes: part of the key of
// cached reference images (bench/image_cache.h), so a changed model is never compared from
// a stale cache. 2: ground-cloud inter-reflection (cloud_lighting.h, ground_cloud_gain);
// 3: the ground under a layer as independent clear and cloudy columns; 4: the peak beam,
// the diffuse source table and the slab transmittances from Monte Carlo (model::
// ms_source_table, model::slab_flux_table); 5: the column depths' quadrature (base shape
// linear between nodes, the threshold's ramp integrated exactly: CloudField::
// column_depths) up to where the profile ends.
inline constexpr int kLightModelRevision = 5;

struct ReferenceSettings {
  // Cloud march
  double cloud_step_m = 5.0;         // primary step inside cloud layers for cumulus (scaled per layer)
  double light_step_m = 10.0;        // light-march and ground-shadow step for cumulus (scaled per layer)
  double min_transmittance = 1e-4;   // the primary march stops below this cloud transmittance (GPU: 1e-3),
                                     // and the background behind is then not evaluated: what is left
                                     // behind contributes < 1e-4 of its own radiance
  double light_cutoff = 1e-4;        // light march stops once the peak beam's e^{-w_D tau} < this (relative
                                     // to the unshadowed sun term of the sample)
  // Atmosphere
  double atmosphere_step_m = 500.0;  // base step of the per-pixel atmosphere integrations (atmo::altitude_step):
                                     // sun transmittance, sky and aerial-perspective single scattering
  double atmosphere_max_step_factor = 20.0;  // longest step along view rays = factor * atmosphere_step_m
  AtmosphereTableSettings tables;    // Psi_ms / E_sky tables: their own quadrature and step (convergence in
                                     // tests/reference_atmosphere_test.cpp); threads are set from `threads`
  // Model variant (see cloud_field.h); false = the shader's definition
  bool honour_stratiform = true;
  // Cumulus layers as individual domes (RendererConfig::cumulus_domes; cloud_field.h)
  bool cumulus_domes = false;
  // The diffuse light's depths from the point's own column (column_optical_depths, the GPU's
  // RenderQuality::column_steps > 0) instead of a homogeneous layer's of the map's coverage.
  bool column_depths = false;
  // Their steps, in light steps: the base shape is read at the steps' ends and linear between
  // them (CloudField::column_depths; 4: 40 m in cumulus, where the diffuse
  // transmittance of the column's depths is within 0.2 % of the field's own integral,
  // tests/reference_column_depths_test.cpp).
  double column_step_factor = 4.0;
  // The sun's diffuse source from a slab tilted towards the sun (tilted_sun_slab in
  // cloud_lighting.h; the GPU's RenderQuality::sun_slab_tilt) instead of the column's
  // horizontal slab. Only with column_depths (as the GPU's, with column_steps > 0).
  bool sun_slab_tilt = false;
  // The noise volumes' stochastic tiling (RendererConfig::noise_tiling; cloud_field.h)
  bool noise_tiling = false;
  // The layers' phase function (RendererConfig::cloud_phase; model/mie_phase_table.h)
  model::CloudPhaseModel cloud_phase = model::CloudPhaseModel::kFit;
  // Rays per pixel along each axis (stratified: the centres of n x n sub-pixels), averaged:
  // 1 = the pixel centre (what the GPU's march samples without footprint jitter).
  int pixel_samples = 1;
  // Shared inputs (sizes and seeds as RendererConfig's defaults)
  InputConfig inputs;
  // Worker threads over image rows (and for the tables), 0 = all cores (common/parallel_for.h);
  // the image does not depend on it.
  int threads = 0;
};

// `base` with the light model a GPU quality draws: the diffuse light's depths from each
// point's own column where the quality's are (RenderQuality::column_steps > 0: high and
// ultra, renderer/quality_presets.cpp), the sun's slab tilted where the quality's is. A GPU
// image is compared with the reference of its own model; against the path-traced truth
// (docs/ACCURACY.md section 0) the models differ.
inline ReferenceSettings same_light_model(const RenderQuality& q, ReferenceSettings base = {}) {
  base.column_depths = q.column_steps > 0;
  base.sun_slab_tilt = base.column_depths && q.sun_slab_tilt;
  return base;
}

// The solar irradiance, the sun's angular radius and the night-sky radiance of the model
// (renderer/model/scene_constants.h, shared with the shaders).
using model::kNightSkyRadiance;
using model::kSolarIrradiance;
using model::kSunAngularRadiusDeg;

// Renders the view (rgba float, rows from the top; rgb radiance in W m^-2 sr^-1 nm^-1 at
// 680/550/440 nm, a = cloud opacity). Stats: render_ms (wall clock, including the first
// call's table and input generation), sun position, cloud_pixels (opacity > kCloudPixelOpacity),
// density_evals_per_pixel (all cloud density evaluations: primary, light, ground shadow; of all
// pixel_samples^2 rays of a pixel),
// nonfinite_pixels (pixels zeroed because of NaN/Inf/negative values; must stay 0).
// wind_anchor: where/when the cloud fields are undisplaced; nullptr = this view.
FrameImage render_reference(const ViewRequest& view, const weather::Weather& weather,
                            const ReferenceSettings& settings = {}, const WindAnchor* wind_anchor = nullptr);

}  // namespace cloudsvc::reference
