// Brute-force Monte Carlo path tracer of the clear-sky atmosphere (issue "independent
// physical checks"): single + all orders of multiple scattering, including Lambertian
// ground bounces, in double precision, per wavelength. It shares the model's *definition*
// (the constants of shaders/atmosphere_model.glsl, mirrored in reference_atmosphere.h) and
// nothing of its evaluation: no transmittance, Psi_ms or sky-view table, no quadrature
// along rays, no multiple-scattering approximation. It is the independent check of
// Hillaire's Psi_ms approximation (Hillaire 2020, "A Scalable and Production Ready Sky and
// Atmosphere Rendering Technique", EGSR, §5: isotropic second order + infinite geometric
// series of f_ms), which the LUT path and the CPU reference both use.
//
// Frame and units: planet-centred Cartesian axes, metres; the camera is on the +z axis at
// radius 6360 km + altitude, so a local East-North-Up direction at the camera is used as
// is (the convention of reference_atmosphere.h). The sun is collimated (at infinity) with
// direction `sun` (unit, towards the sun, the same at every point) and irradiance
// sun_irradiance perpendicular to the beam (1 by default: radiances are then "for unit
// solar irradiance", sr^-1, as in reference_atmosphere.h; multiply by the solar spectral
// irradiance to get W m^-2 sr^-1 nm^-1). Channel c = 0, 1, 2 is 680, 550, 440 nm.
//
// Medium: spherical shell 6360-6460 km; Rayleigh scattering beta_R exp(-h / 8 km) (phase
// 3/(16 pi)(1 + nu^2)), aerosol scattering 3.996e-6 / extinction 4.44e-6 /m exp(-h / 1.2 km)
// (Cornette-Shanks phase, g = 0.8), ozone absorption in a tent 10-25-40 km; ground a
// Lambertian sphere of albedo GROUND_ALBEDO_ATMO at 6360 km; nothing above 100 km.
//
// Estimator (all unbiased; Novak et al. 2018, "Monte Carlo methods for volumetric light
// transport simulation", CGF 37(2), §§4-5, for delta and ratio tracking):
//   - majorants: piecewise constant in altitude bands (20 bands, 0.5 km wide near the
//     ground, 20 km at the top), each a rigorous upper bound of the extinction in its band
//     (exponentials at the band's bottom + the tent's maximum over the band); a straight ray
//     is split where it crosses the band spheres, and tentative collisions are sampled as a
//     Poisson process of the majorant along it;
//   - camera ray: ratio tracking (weight w *= 1 - sigma_t / sigma_maj at each tentative
//     collision, majorant scaled by primary_majorant_scale for more samples) and, at every
//     tentative collision x, (a) next-event estimation towards the sun,
//       w (sigma_R p_R + sigma_M p_M)(nu) / sigma_maj T_sun(x)      (single scattering), and
//     (b) one secondary path with weight w sigma_s / sigma_maj, its direction sampled from
//     the Rayleigh/aerosol phase mixture, estimating the diffuse in-scattered radiance
//     (multiple scattering); E[sum over tentative collisions of w f / sigma_maj] =
//     Int T(0, t) f(t) dt;
//   - secondary paths: delta tracking (free flights by the same banded majorants), NEE
//     towards the sun at every tentative collision (weighted sigma_s p / sigma_maj as above)
//     and at every ground hit (albedo / pi (n . sun) T_sun); at a real collision (probability
//     sigma_t / sigma_maj) the throughput is multiplied by sigma_s / sigma_t and the
//     direction sampled from the phase mixture (Rayleigh by its analytic inverse CDF,
//     Cornette-Shanks by rejection from Henyey-Greenstein), at the ground by albedo and a
//     cosine-weighted direction; Russian roulette once the throughput fell below 5 % of the
//     path's starting weight; paths end when they leave through the top;
//   - sun transmittance T_sun(x): ratio tracking along the sun direction (0 if the ray
//     hits the ground: the planet's shadow).
// The single-scattering part is the expected value of the camera-ray NEE alone and is
// reported separately (so is the rest: orders >= 2 and ground bounces).
//
// Parallel and deterministic: the camera paths are cut into fixed chunks of
// kPathsPerChunk, each traced with its own PCG32 stream (model::chunk_stream of the seed
// and channel, and the chunk index) into its own sums; the chunk sums are added in chunk
// order. An estimate depends on (atmosphere, geometry, channel, paths, seed) only, not on
// the thread count.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/model/slab_monte_carlo.h"  // model::Pcg32, model::chunk_stream
#include "renderer/reference/reference_atmosphere.h"

namespace cloudsvc::reference::mc {

// The atmosphere to trace (defaults: the model's constants; tests change them for cases
// with known answers).
struct McAtmosphere {
  glm::dvec3 rayleigh_scattering = atmo::kRayleighScattering;  // 1/m at sea level
  double rayleigh_scale_height = atmo::kRayleighScaleHeight;   // m
  double mie_scattering = atmo::kMieScattering;                // 1/m at sea level
  double mie_extinction = atmo::kMieExtinction;                // 1/m at sea level
  double mie_scale_height = atmo::kMieScaleHeight;             // m
  double mie_g = atmo::kMieG;                                  // Cornette-Shanks asymmetry
  glm::dvec3 ozone_absorption = atmo::kOzoneAbsorption;        // 1/m at the tent's peak (25 km)
  glm::dvec3 ground_albedo = atmo::kGroundAlbedo;              // Lambertian
  double sun_irradiance = 1.0;  // collimated sun, perpendicular irradiance (0: no sun)
  double top_radiance = 0.0;    // isotropic radiance entering through the top (white-furnace test)
};

struct McSettings {
  long long paths = 100000;            // camera paths per estimate
  int max_order = 1 << 20;             // highest scattering order counted (1: single scattering only)
  double primary_majorant_scale = 8.0; // camera-ray majorant / band majorant (>= 1; more NEE + secondaries)
  int threads = 0;                     // worker threads, 0 = all cores (common/parallel_for.h); no effect on results
  std::uint64_t seed = 1;
};

// Camera paths per chunk of work (see above): 10-80 us per path on one core, so 1-10 ms per
// chunk; 10 000 paths are 79 chunks, enough to keep 16 threads busy to the end.
inline constexpr long long kPathsPerChunk = 128;

// Mean over paths and its standard error (sample standard deviation / sqrt(paths)).
struct McValue {
  double mean = 0.0, std_error = 0.0;
};

struct McEstimate {
  McValue total;     // single + multiple (+ top_radiance term), sr^-1 for unit irradiance
  McValue single;    // camera-ray NEE (single scattering of the sun)
  McValue multiple;  // everything else: orders >= 2, ground bounces, top illumination
  long long paths = 0;
  double seconds = 0.0;  // wall time
};

// Sky radiance seen from altitude camera_alt_m (m above the 6360 km sphere) in direction
// view (unit, local ENU at the camera = planet axes), sun direction sun (unit), channel c.
McEstimate sky_radiance(const McAtmosphere& atmosphere, double camera_alt_m, const glm::dvec3& view,
                        const glm::dvec3& sun, int channel, const McSettings& settings);

// Phase functions (sr^-1) and their samplers (cosine of the scattering angle), exposed for
// the tests.
double rayleigh_phase(double nu);
double cornette_shanks_phase(double nu, double g);
double sample_rayleigh_cos(double u);  // analytic inverse CDF (Cardano)
double sample_cornette_shanks_cos(double g, model::Pcg32& rng);

// Optical-depth majorant band edges (altitudes, m) and the band majorant of a channel.
int majorant_band_count();
double majorant_band_bottom(int band);  // band i is [bottom(i), bottom(i + 1)], bottom(count) = 100 km
double band_majorant(const McAtmosphere& atmosphere, int channel, int band);
// Extinction (1/m) of a channel at altitude h (m); 0 above the top.
double extinction_at(const McAtmosphere& atmosphere, int channel, double altitude_m);
// Transmittance to the sun from altitude h with sun zenith cosine mu_s, by ratio tracking
// (one estimate; the tests average many against the integrated value).
double sun_transmittance_ratio_tracking(const McAtmosphere& atmosphere, int channel, double altitude_m,
                                        double mu_s, model::Pcg32& rng);

}  // namespace cloudsvc::reference::mc
