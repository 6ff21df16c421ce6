// The clear-sky atmosphere of the model (docs/RENDERING.md "Atmosphere"; Hillaire 2020,
// "A Scalable and Production Ready Sky and Atmosphere Rendering Technique", EGSR; constants
// in renderer/model/atmosphere_constants.h), evaluated by direct numerical integration in
// double precision, no LUTs.
//
// Geometry: the atmosphere is spherically symmetric with its own radii (ground 6360 km,
// top 6460 km), independent of the cloud-shell radius: a point is given by its radius r
// from the planet centre (or its altitude r - 6360 km) and a direction by its zenith
// cosine mu relative to the local up. A ray starting at radius r0 is traced in a frame
// with the start on the +z axis, so a local ENU direction d at the start is used as is.
//
// Units: lengths in m, coefficients in 1/m, radiances for a unit solar irradiance
// (multiply by the solar spectral irradiance, W m^-2 nm^-1, to get W m^-2 sr^-1 nm^-1),
// rgb = 680, 550, 440 nm.
#pragma once

#include <glm/glm.hpp>

#include "renderer/model/atmosphere_constants.h"
#include "renderer/model/scene_constants.h"

namespace cloudsvc::reference::atmo {

// The atmosphere's constants (renderer/model/atmosphere_constants.h, shared with the
// shaders) and the ground albedo its multiple scattering sees.
using model::atmosphere::kBottomRadius;
using model::atmosphere::kMieExtinction;
using model::atmosphere::kMieG;
using model::atmosphere::kMieScaleHeight;
using model::atmosphere::kMieScattering;
using model::atmosphere::kOzoneAbsorption;
using model::atmosphere::kRayleighScaleHeight;
using model::atmosphere::kRayleighScattering;
using model::atmosphere::kTopRadius;
constexpr double kThickness = kTopRadius - kBottomRadius;
constexpr glm::dvec3 kGroundAlbedo{model::kGroundAlbedo[0], model::kGroundAlbedo[1], model::kGroundAlbedo[2]};

// Medium at an altitude (clamped to >= 0: points below the atmosphere's ground, which the
// cloud shell geometry can produce, get ground-level air). aerosol_scale, here and below:
// the factor on the aerosol's scattering and extinction (model::atmosphere::aerosol_scale_of
// the weather's visibility; 1 = the model's own haze).
struct Medium {
  glm::dvec3 rayleigh_scattering{0.0};  // 1/m
  double mie_scattering = 0.0;          // 1/m
  glm::dvec3 extinction{0.0};           // Rayleigh + Mie extinction + ozone absorption, 1/m
};
Medium medium_at(double altitude_m, double aerosol_scale = 1.0);
// The largest extinction (rgb, 1/m) of medium_at over altitudes [a0, a1] (a0 <= a1): the
// exponentials at max(a0, 0), the ozone tent at its highest point in the interval. A
// rigorous bound, for majorants.
glm::dvec3 max_extinction(double a0, double a1, double aerosol_scale = 1.0);

// Phase functions (sr^-1) of the cosine nu between the view and sun directions.
double rayleigh_phase(double nu);  // 3 / (16 pi) (1 + nu^2)
double mie_phase(double nu);       // Cornette-Shanks, g = kMieG

// Radius used for a point at altitude alt: clamped to [bottom + 1 m, top - 1 m] as the
// model's lookups do (a camera above 100 km sees the atmosphere from its top).
double radius_for_altitude(double altitude_m);
// Does the ray from radius r with zenith cosine mu hit the ground sphere?
bool ray_hits_ground(double r, double mu);
double distance_to_top(double r, double mu);
double distance_to_bottom(double r, double mu);
// Length of the path to the ground if the ray hits it, else to the top.
double path_length(double r, double mu);

// Step control of the brute-force integrations. A step is chosen so that the altitude
// changes by at most s(alt) = step_m (1 + alt / 8 km) along it (alt >= 0):
//   dt = 2 s / (|mu| + sqrt(mu^2 + 2 s / r)),
// i.e. the step of equal altitude change for a straight ray (mu dt + dt^2 / 2r = s); near
// the tangent point of a horizontal ray it grows to sqrt(2 r s) (80 km for 500 m), where
// the air changes slowly. max_step_m bounds it further where the integrand also depends
// on the horizontal position (the local sun zenith angle on view rays).
double altitude_step(double r, double mu, double step_m);

// Optical depth (rgb) of an extinction profile extinction(alt) (1/m, alt in m above the
// ground sphere) along the straight ray from radius r with zenith cosine mu over
// [0, length]: altitude_step steps, two-point Gauss-Legendre quadrature on each (fourth
// order in the step for a smooth profile).
template <class Extinction>
glm::dvec3 integrate_optical_depth(double r, double mu, double length, double step_m, const Extinction& extinction);
// ... of this atmosphere (medium_at(alt).extinction).
glm::dvec3 optical_depth(double r, double mu, double length, double step_m, double aerosol_scale = 1.0);

// The model's transmittance to space: from altitude alt (above the atmosphere's ground)
// along zenith cosine mu to the top; 0 when the ray hits the planet (the sun below the
// horizon). exp(-optical depth), integrated (no table).
glm::dvec3 transmittance_to_space(double altitude_m, double mu, double step_m, double aerosol_scale = 1.0);

// In-scattered radiance and transmittance along a straight ray.
struct RayInscatter {
  glm::dvec3 radiance{0.0};       // for unit solar irradiance, sr^-1
  glm::dvec3 transmittance{1.0};
};

// Integrates, from t = 0 to t_end along direction d from radius r0 (d, sun in the frame
// with the start on +z), the single scattering of the sun (Rayleigh and aerosol phase,
// sun transmittance from sun_transmittance(alt, mu_sun)) plus Hillaire's isotropic
// multiple scattering (sigma_s * psi_ms(alt, mu_sun), eq. 11 of Hillaire 2020):
//   L = int T(0, t) S(t) dt,   S = (sigma_R p_R + sigma_M p_M) T_sun + (sigma_R + sigma_M) Psi_ms,
// with the energy-conserving step of Hillaire 2016 (S constant over a step, exact
// transmittance: T S (1 - e^{-sigma dt}) / sigma). skip_above_top leaves out samples at
// or above the top of the atmosphere (the aerial-perspective definition).
template <class SunTransmittance, class MultipleScattering>
RayInscatter integrate_inscatter(double r0, const glm::dvec3& d, const glm::dvec3& sun, double t_end,
                                 bool skip_above_top, double step_m, double max_step_m,
                                 const SunTransmittance& sun_transmittance, const MultipleScattering& psi_ms,
                                 double aerosol_scale = 1.0);

}  // namespace cloudsvc::reference::atmo

#include "renderer/reference/reference_atmosphere_inl.h"
