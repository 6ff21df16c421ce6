// A double-precision transcription of what the GPU cloud march (shaders/cloud_march.comp,
// its light in shaders/cloud_lighting.glsl) computes for a homogeneous plane-parallel
// slab: the "model of the model" that the Monte Carlo slab (slab_monte_carlo.h) is compared against. It is deliberately literal:
// every step names the shader function or variable it mirrors, and nothing here is tuned.
//
// Scene: flat slab base z = 0, top z = H (the shader's shells, with the planet radius
// taken to infinity), sigma = sigma_t everywhere inside (coverage 1, density scale 1,
// density modulation 1, no noise), sun irradiance E_sun = 1 (normal to the beam),
// atmosphere transmittance T_atm = 1, sky irradiance E_sky = 0, ground albedo 0 (sun
// only), no aerial perspective. A camera above the slab looking down sees the reflected
// radiance; below looking up, the transmitted radiance. The result is the cloud term C
// of cloud_march.comp, C += T * absorbed * (L_sun + L_diffuse) (the background T · L_bg
// is excluded: it holds the direct sun, which the Monte Carlo radiances exclude as well). Units: L / E_sun in sr^-1.
#pragma once

#include "renderer/model/ms_source_table.h"
#include "renderer/model/slab_monte_carlo.h"
#include "renderer/model/scene_constants.h"
#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc::model {

struct SlabRendererModelOptions {
  // RenderQuality defaults (renderer/api/render_quality.h), as the shader receives them in
  // the frame uniforms (renderer/frame_uniforms.h, same names).
  int primary_steps = RenderQuality{}.primary_steps;
  int light_steps = RenderQuality{}.light_steps;
  // Primary steps are uniform in t here, at least min_step_m long; cloud_march.comp steps
  // uniformly in march_coordinate (ln(1 + t / t_ref)) without such a floor.
  double min_step_m = 1.0;
  bool cap_light_march = true;                   // light_optical_depth: len = min(len, LIGHT_MARCH_REACH_M)
  double light_max_dist_m = kLightMarchReach_m;  // LIGHT_MARCH_REACH_M (scene_constants.h)
  bool diffuse = true;                           // cloud_march.comp: L_diffuse = diffuse_inscatter(...)
  // false: the sun term is single scattering alone (phase e^-tau) instead of the peak beam
  // (peak_beam_phase); a check of the march, not the shader.
  bool peak_beam = true;
  double cloud_t_eps = 1e-3;  // CLOUD_T_EPS, cloud_march.comp: early exit
  // The shader jitters the sample within each step per pixel (cloud_march.comp: jitter from
  // hash12, t = march_distance(u0 + (st + jitter) du)). The
  // model averages over jitter_samples stratified jitters (j + 0.5) / n, i.e. the
  // expected pixel value; 1 = the step midpoint.
  int jitter_samples = 1;
  // Experiment (bench/slab_mc_table --ms-source-column): the diffuse source from this
  // Monte Carlo column (for this slab's optical depth and sun) instead of the table's
  // interpolation (ms_source_table()), to tell the model's error from the table's.
  const MsSourceColumn* ms_source_column = nullptr;
};

// Options for a converged march of the same light model: many primary steps, so the
// difference to the Monte Carlo is the lighting approximation, not the step size.
SlabRendererModelOptions converged_renderer_model_options();

struct SlabRendererModelResult {
  double radiance = 0.0;          // C / E_sun, sr^-1 (sun octaves + diffuse)
  double radiance_sun = 0.0;      // the peak-beam (L_sun) part
  double radiance_diffuse = 0.0;  // the diffuse_inscatter part
  double transmittance = 1.0;     // T along the view ray at the end of the march
};

// Radiance of the slab in the view direction v (ViewDirection of slab_monte_carlo.h: the
// travel direction of the light leaving the top if `top`, else the bottom).
SlabRendererModelResult slab_renderer_model_radiance(const SlabSpec& slab, const ViewDirection& v, bool top,
                                                     const SlabRendererModelOptions& options = {});

// Sun part pieces, exposed for tests: the light-march optical depth from height z (m) to
// the slab top towards a sun with cosine mu_s (light_optical_depth, cloud_lighting.glsl),
// and the diffuse in-scatter per unit scattering (diffuse_inscatter, same file) in sr^-1
// of light travelling in direction w (travel, z up; the sun lies towards +x).
double slab_light_optical_depth(const SlabSpec& slab, double z, const SlabRendererModelOptions& options);
double slab_diffuse_inscatter(const SlabSpec& slab, double z, const SlabRendererModelOptions& options,
                              const glm::dvec3& w);

}  // namespace cloudsvc::model
