// Monte Carlo radiative transfer in a homogeneous, plane-parallel, conservatively
// scattering slab (single-scattering albedo 1) with the Jendersie & d'Eon 2023 droplet
// phase function, lit by a collimated sun, black ground, no atmosphere. An independent
// check of the renderer's multiple-scattering approximation (docs/ACCURACY.md §4): the
// transport here is exact up to Monte Carlo noise, nothing is fitted.
//
// Method: photon random walk with delta (Woodcock) tracking against a majorant
// (Woodcock et al. 1965; pbrt-v4 ch. 14 "majorant tracking"); in a homogeneous slab the
// majorant equals sigma_t and every tentative collision is real, but the loop is written
// for sigma_t(z) <= majorant. Fluxes by counting (weighted) escapes; radiance leaving the
// top or bottom by next-event estimation at every real collision (phase × attenuation to
// the boundary), with detector-directional importance sampling of the scattering
// direction near the boundaries (see SlabMcOptions). Deterministic: fixed chunks of
// photons, each with its own PCG32 stream, merged in chunk order, so results do not
// depend on the thread count or scheduling.
//
// Units: lengths in metres, extinction in 1/m. Radiances are per unit solar irradiance
// measured normal to the beam (sr^-1), i.e. L / F_sun; fluxes are fractions of the
// incident horizontal flux mu0 · F_sun.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "renderer/model/phase_function.h"

namespace cloudsvc::model {

// The slab and its illumination, shared with the renderer model (slab_renderer_model.h).
struct SlabSpec {
  double sigma_t_per_m = 0.0;       // extinction coefficient (homogeneous), 1/m
  double thickness_m = 0.0;         // geometric thickness H; base at z = 0, top at z = H
  double sun_zenith_deg = 0.0;      // 0..89: collimated sun from above
  double droplet_diameter_um = 14.0;  // JdD phase (r_e = 7 um as in Bouthors et al. 2008 §3.2)

  double optical_depth() const { return sigma_t_per_m * thickness_m; }
};

// A slab of optical depth tau with the extinction of droplet_optics.h for the given
// droplet diameter (N0 = 300 cm^-3, Q_ext = 2), so thickness = tau / sigma_t.
SlabSpec slab_from_optical_depth(double tau, double sun_zenith_deg, double droplet_diameter_um = 14.0);

// Direction of the light leaving the slab: view zenith angle (0..89°) measured from the
// outward normal (up for the top, down for the bottom), and azimuth of the light's travel
// direction relative to the sun's azimuth: 0 = travelling towards the sun's side,
// 180 = away from it. The observer looks along the opposite direction, so 0 is an
// observer looking away from the sun (backscatter side of the cloud top; the cloud base
// opposite the sun) and 180 one looking towards it (forward-scatter side of the top; the
// aureole around the sun seen from below).
struct ViewDirection {
  double zenith_deg = 0.0;
  double rel_azimuth_deg = 0.0;
};

// Unit vector of the light's travel direction for a view leaving the top (top = true) or
// bottom; the sun direction (towards the sun) is (sin θ0, 0, cos θ0). z is up.
glm::dvec3 view_travel_direction(const ViewDirection& v, bool top);
glm::dvec3 sun_direction(double sun_zenith_deg);  // towards the sun
// Unit direction at angle acos(cos_t) from the unit vector d, azimuth phi (radians)
// about it (any d, including ±z).
glm::dvec3 scatter_direction(const glm::dvec3& d, double cos_t, double phi);

struct SlabMcOptions {
  std::uint64_t photons = 100000;
  std::uint64_t seed = 1;
  int threads = 0;                          // worker threads, 0 = all cores (common/parallel_for.h)
  int chunks = 64;                          // work units, each with its own PCG32 stream (chunk_stream)
  std::uint64_t max_collisions = 10000000;  // per history (photon and its copies); beyond it: lost
  // Next-event contributions attenuated by more than this optical depth along the view
  // are skipped: bias < e^-40 · max(p)/mu ~ 1e-14 sr^-1, saves most of the cost deep in
  // thick slabs.
  double nee_max_optical_depth = 40.0;
  std::vector<ViewDirection> views;         // evaluated both at the top and at the bottom
  // Detector-directional importance sampling (DDIS, Buras & Mayer 2011, JQSRT 112, 434):
  // the droplet phase has a forward peak of ~0.5° (g_HG = 0.992 at 14 um), so plain
  // next-event estimates are dominated by the rare photons that travel within that peak
  // of a view direction. At collisions within ddis_max_optical_depth (along a view) of a
  // boundary, with probability ddis_probability a weighted copy of the photon is spawned
  // whose direction is drawn from the phase peak about one of the reachable view
  // directions; photon and copy are weighted by multi-sample MIS (balance heuristic), so
  // weights stay <= 1 and nothing is biased. 0 = analog transport.
  // Defaults from a sweep over tau 1..64, sun 0/60°, views 0/60°: ~3-5x less variance
  // per CPU second than analog transport (whose error estimates are also unreliable:
  // heavy-tailed).
  double ddis_probability = 0.3;
  double ddis_max_optical_depth = 4.0;
  // Russian roulette for weights below this (survivors get twice this weight).
  double weight_roulette_below = 0.3;
};

// Mean and standard error of the mean (from the sample variance over photon histories,
// which are independent and identically distributed).
struct Estimate {
  double mean = 0.0;
  double std_error = 0.0;
};

struct SlabMcResult {
  Estimate reflected;             // R: fraction of the incident flux leaving the top
  Estimate transmitted;           // T: total (direct + diffuse) leaving the bottom
  Estimate transmitted_diffuse;   // T minus the unscattered beam
  Estimate transmitted_direct;    // unscattered beam (expectation e^{-tau/mu0})
  // R + T per history: expectation 1 (conservative scattering); exactly 1 per history
  // with analog transport (ddis_probability = 0), unless photons are lost.
  Estimate reflected_plus_transmitted;
  // Per view (same order as options.views), L / F_sun in sr^-1: all orders, and the
  // single-scattering part alone (first collision only).
  std::vector<Estimate> radiance_top, radiance_bottom;
  std::vector<Estimate> radiance_top_single, radiance_bottom_single;
  std::uint64_t photons = 0;
  std::uint64_t lost_photons = 0;     // exceeded max_collisions
  double mean_collisions = 0.0;       // real collisions per photon
  double seconds = 0.0;               // wall time
};

SlabMcResult run_slab_monte_carlo(const SlabSpec& slab, const SlabMcOptions& options);

// ---- building blocks, exposed for tests ----

// PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation"): 64-bit LCG state, XSH-RR output.
class Pcg32 {
 public:
  Pcg32(std::uint64_t seed, std::uint64_t stream);
  std::uint32_t next_u32();
  double uniform();  // [0, 1) with 53 random bits
 private:
  std::uint64_t state_ = 0;
  std::uint64_t inc_ = 0;
};

// The PCG32 stream of work chunk `chunk` of a Monte Carlo run with seed `seed`: stream
// (increment) `chunk`, state seed decorrelated by SplitMix64 (Steele, Lea & Flood 2014) of
// seed and chunk. A run split into fixed chunks, each drawing from its own stream, and
// merged in chunk order gives the same result on any number of threads.
Pcg32 chunk_stream(std::uint64_t seed, std::uint64_t chunk);

// Cosine of the scattering angle sampled from the HG lobe (analytic inverse CDF).
double sample_hg_cos_theta(double g, double u);
// Cosine of the scattering angle sampled from the JdD blend: lobe chosen by weight
// (1 - w_D : w_D), HG by its analytic inverse CDF, Draine by rejection from HG(g_D) with
// acceptance (1 + alpha mu^2) / (1 + alpha) (mean acceptance ~0.55 for d = 5..50 um).
double sample_jdd_cos_theta(const JdDParams& p, Pcg32& rng);
// Cosine sampled from the Draine lobe alone (the rejection step above).
double sample_draine_cos_theta(double g, double alpha, Pcg32& rng);

}  // namespace cloudsvc::model
