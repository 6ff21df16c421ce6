// Light in the clouds (docs/RENDERING.md "Light"), converged: the sun's peak beam through a
// fine light march, the diffuse term (Monte Carlo source tables for the sun's light and for
// the sky's and the ground's diffuse light, Monte Carlo slab transmittances to the ground),
// and cloud shadows on the
// ground through a fine march of every layer. Frames and units as in reference_scene.h;
// optical depths dimensionless; radiances in the units of the solar irradiance given.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/model/scene_constants.h"
#include "renderer/model/slab_flux_table.h"
#include "renderer/reference/cloud_field.h"

namespace cloudsvc::reference {

// The model's light-march reach (renderer/model/scene_constants.h, shared with the shaders).
inline constexpr double kLightMarchCap_m = model::kLightMarchReach_m;

// Step scale of a layer: cloud_step_m and light_step_m are for cumulus (8 km noise period,
// peak extinction ~0.15 /m). A layer whose noise features are larger (period / 8 km,
// divided by the noise vertical scale where it exceeds 1) gets
// proportionally longer steps unless its peak extinction sigma_max * density_scale * 2
// (the weather map doubles density at most) would then make a step optically thicker than
// a cumulus step. Clamped to [1, 8]: optically denser layers (cumulonimbus, peak 0.3 /m)
// keep the base steps (docs/REFERENCE.md shows they converge there too). Halving the base
// steps halves every layer's steps, so convergence tests apply.
double layer_step_scale(const ReferenceLayer& layer);

// Sun optical depth of layer li from local point p (altitude alt, sun zenith cosine mu_s
// there) along the sun direction: midpoint rule with steps <= step_m over
// [0, min(exit through the top, entry through the base, 4 km)], without detail erosion
// (the model's light march uses the base shape only). Stops early once the depth exceeds
// tau_stop (beyond it the peak beam's e^{-w_D tau} is negligible).
// marched_m (if given) receives the length marched: the whole path, or up to the early stop.
double light_optical_depth(const CloudField& field, int li, const glm::dvec3& p, double alt, const glm::dvec3& sun,
                           double mu_s, double step_m, double tau_stop, std::uint64_t& evals,
                           double* marched_m = nullptr);

// The optical depths above and below a point through its own vertical column of layer li,
// to the layer's top and base: the independent column approximation (Cahalan et al. 1994,
// J. Atmos. Sci. 51, 3776) in which the diffuse light at a point is that of a plane-parallel
// slab with the optical depths of the cloud actually above and below it: from the layer's
// base to where its profile ends, in steps <= step_m of CloudField::column_depths (the GPU's
// quadrature), without detail erosion (as the
// light march), no reach cap.
struct ColumnDepths {
  double above = 0.0, below = 0.0;
};
ColumnDepths column_optical_depths(const CloudField& field, int li, const glm::dvec3& p, double alt, double step_m,
                                   std::uint64_t& evals);
// ... of a homogeneous layer of the map's coverage instead: the layer's nominal extinction
// sigma_max * density_scale * coverage times the distances to its top and to its base
// raised by a textured base's mean lift (CloudField::nominal_base_m; the GPU's
// RenderQuality::column_steps = 0).
ColumnDepths nominal_column_depths(const ReferenceLayer& L, double alt, double coverage);

// The slab the sun's diffuse source is read from (model::ms_source_table), tilted towards the
// sun: side illumination of 3-D clouds. A plane-parallel slab takes the sun through its
// horizontal top at the sun's zenith cosine mu_s; near the sunlit side of a cumulus under a
// low sun the light arrives through a face that looks towards the sun, at a cosine closer
// to 1 and much less deep. As in the tilted independent column approximation (Varnai &
// Davies 1999, J. Atmos. Sci. 56, 4206; Wapler & Mayer 2008, J. Appl. Meteor. Climatol. 47,
// 3061) the sun's depth is read along the sun's own path (the light march); the slab's
// normal is turned towards the sun until that path crosses it at the depth the point's
// vertical column gives:
//   mu' = clamp(w tau_a / tau_sun, mu_s, 1),
// tau_sun the light march's depth over the part of the path it marched, w the fraction of
// the column above the point that part spans vertically (sun_window: 1 unless the march
// stopped at its reach or cut-off; the rest of the column keeps its vertical depth). In a
// horizontally homogeneous slab tau_sun = w tau_a / mu_s and the slab is the horizontal one
// (mu' = mu_s) exactly; with the sun's path leaving the cloud through a side, mu' -> 1.
// The slab's depths: above = mu' tau_sun + (1 - w) tau_a, below = tau_b + max(tau_a -
// above, 0) (the cloud the sun's path does not cross stays behind the point). The scattered
// light's direction is measured from the tilted normal (w_n, cos_phi about it).
struct SunSlab {
  double mu = 1.0;                  // cosine between the slab's normal and the sun
  double above = 0.0, below = 0.0;  // optical depths from the point to the sunlit face, and beyond it
  double w_n = 1.0;                 // cosine between the scattered light's direction and the normal
  double cos_phi = 1.0;             // azimuth of that direction from the sun's, about the normal
};
// The horizontal slab of the column (no tilt), from the local vertical up, the unit sun
// direction and the scattered light's w.
SunSlab vertical_sun_slab(const ColumnDepths& column, const glm::dvec3& up, const glm::dvec3& sun, const glm::dvec3& w);
// up: local vertical, sun: unit sun direction, w: unit direction of the scattered light
// (towards the camera); tau_sun, window: light_optical_depth and sun_window. No sun
// (mu_s <= 0) or the sun overhead: the vertical slab.
SunSlab tilted_sun_slab(const ColumnDepths& column, double tau_sun, double window, const glm::dvec3& up,
                        const glm::dvec3& sun, const glm::dvec3& w);
// The fraction of the column above a point (to_top_m below the layer's top) that a light
// march of marched_m towards a sun of zenith cosine mu_s spans vertically, at most 1.
double sun_window(double marched_m, double mu_s, double to_top_m);

// Optical depth of all layers from a ground point (local p, altitude ground_alt) towards
// the sun, midpoint rule with each layer's step (light_step_m * layer_step_scale) between
// the sun ray's crossings of the layer's base and top; no detail erosion.
double ground_shadow_optical_depth(const CloudField& field, const glm::dvec3& p, double ground_alt,
                                   const glm::dvec3& sun, double mu_s, double light_step_m, std::uint64_t& evals);

// Optical depth of layer li alone along the sun ray from local point p (altitude alt, sun
// zenith cosine mu_s there) below or inside it, between the ray's crossings of the layer's
// base and top; midpoint rule with the layer's step (light_step_m * layer_step_scale), no
// detail erosion. The part of ground_shadow_optical_depth for one layer.
double layer_sun_optical_depth(const CloudField& field, int li, const glm::dvec3& p, double alt, const glm::dvec3& sun,
                               double mu_s, double light_step_m, std::uint64_t& evals);

// The light a layer receives through the layers above it (twin of shaders/layers_above.glsl).
// Optical depth towards the sun, along the slant path, of the layers above layer li (those
// whose base is at or above li's top) from local point p: layer_sun_optical_depth summed.
double layers_above_optical_depth(const CloudField& field, int li, const glm::dvec3& p, double alt,
                                  const glm::dvec3& sun, double mu_s, double light_step_m, std::uint64_t& evals);
// What layers of slant optical depth tau towards the sun let through to a layer below whose
// diffuse reflectance from above is r_low, as factors of the light above the clouds: the
// sun's direct beam e^-tau; the sky's diffuse light T_dif(tau_v) g; the sun's light arriving
// diffuse, T_beam(tau_v, mu0) g - e^-tau (per unit horizontal solar flux); tau_v = tau mu_s
// their vertical optical depth as a plane-parallel slab, g = 1 / (1 - r_low (1 - T_dif(tau_v)))
// the round trips between the two (the adding method; Liou 2002 §6.2). tau = 0: {1, 1, 0}.
struct LightFromAbove {
  double direct = 1.0, sky = 1.0, sun_diffuse = 0.0;
};
LightFromAbove layers_above_light(double tau, double mu_s, double r_low);
// Diffuse reflectance from above of layer L where the map's coverage is c: c (1 - T_dif) of
// its full optical depth.
double layer_diffuse_reflectance(const ReferenceLayer& L, double coverage);

// The sun's light scattered towards the camera per unit sun irradiance after a light-march
// optical depth tau (sr^-1, rgb): the peak beam (model::peak_beam_phase: single scattering
// and the light scattered only through the diffraction peak). Where `mie` is given, single
// scattering uses that table instead of the fit (per wavelength: the glory and fogbow).
glm::dvec3 sun_phase(const model::JdDParams& phase, const model::PhaseTable* mie, double cos_view_sun, double tau);

// The transmittance of a conservative slab, for diffuse light and for the sun's beam: the
// Monte Carlo table of renderer/model/slab_flux_table.h.
using model::slab_beam_transmittance;
using model::slab_diffuse_transmittance;

// Ground-cloud inter-reflection: 1 / (1 - a R(tau)), R = 1 - slab_diffuse_transmittance(tau)
// the diffuse reflectance from below of the clouds above a ground of albedo a (per channel;
// the adding method). Twin of ground_cloud_gain in shaders/slab_transmittance.glsl.
glm::dvec3 ground_cloud_gain(const glm::dvec3& albedo, double tau);

// Diffuse in-scattered radiance per unit scattering at altitude alt inside layer L
// (docs/RENDERING.md; diffuse_inscatter in shaders/cloud_lighting.glsl) at a point whose
// column has the optical depths `column` above and below it (column_optical_depths).
// The sun's part: model::ms_source_table() at the depths of the sun's slab (scaled by
// model::ms_similarity_scale; tilted_sun_slab, or vertical_sun_slab) times the solar flux
// through its face F_sun = e_sun t_atm mu', for the scattered light's cosine and azimuth
// about the slab's normal. The sky's and the ground's
// parts: model::ms_diffuse_incidence_table() (the Monte Carlo source of diffuse light entering
// through the top), J = E_sky J_dif(tau_a, tau_b, w_up) + E_up J_dif(tau_b, tau_a, -w_up),
// the ground's light entering through the base (the table turned upside down); E_up = a E_g
// is the light the ground sends up: its irradiance E_g under the layer as independent
// columns (1 - c in the clear, c = the map's coverage at the point, under the layer's full optical depth tau_c = sigma_max *
// density_scale * thickness; sun and sky at ground level) with the ground-cloud round trips
// (ground_cloud_gain(c a, tau_c)).
// above: what the layers above the point let through (layers_above_light), applied to the
// sun's source, the light entering the top (the sun's scattered part joins the sky's) and the
// ground's irradiance alike.
// Inputs per unit solar irradiance except e_sun: t_atm = sun transmittance at the point,
// e_sky_here = sky irradiance at the point, t_atm_ground / e_sky_ground at ground level
// for the same mu_s; ground_albedo rgb.
// w_up: the scattered light's zenith cosine (for the sky's and the ground's parts).
glm::dvec3 diffuse_inscatter(const ReferenceLayer& L, const ColumnDepths& column, const SunSlab& sun_slab, double mu_s,
                             double coverage, const glm::dvec3& e_sun, const glm::dvec3& t_atm,
                             const glm::dvec3& e_sky_here, const glm::dvec3& t_atm_ground,
                             const glm::dvec3& e_sky_ground, const glm::dvec3& ground_albedo, double w_up,
                             const LightFromAbove& above = {});

}  // namespace cloudsvc::reference
