// The estimator of the ground truth: one light path per call, every order of scattering,
// unbiased, in double precision, through a TruthWorld (truth_world.h).
//
// Estimator (Novak et al. 2018, "Monte Carlo methods for volumetric light transport
// simulation", CGF 37(2); Kutz et al. 2017, "Spectral and decomposition tracking for
// rendering heterogeneous volumes", ACM TOG 36(4); Veach 1997, PhD thesis, ch. 9, for
// multiple importance sampling):
//   - free flights by delta tracking against the band majorant (band_walker.h), all three
//     channels at once by spectral tracking: at a tentative collision with majorant m and
//     path throughput beta (rgb), a real scattering, a null collision or absorption is
//     chosen with probability <beta sigma> / (<beta> m) (<.> = mean over the channels)
//     and beta_c multiplied so that every channel's expectation is its own delta
//     tracking's (Kutz et al. 2017, §4, "history-aware" weights); at a real scattering the
//     new direction comes from one component's phase function, the component picked in
//     proportion to <beta sigma_k>, and beta_c *= f_c / (s pdf) with f the scattering
//     kernel sum_k sigma_k p_k and s = <beta sigma_s> / <beta>;
//   - the sun is the model's disk (angular radius sun_angular_radius_rad; 0 = collimated,
//     reached by next-event estimation alone). Sunlight scattered at a point y is
//     estimated two ways, combined by the balance heuristic: (A) next-event estimation at
//     tentative collisions (with probability q = min(1, nee_boost max_c sigma_s,c / m):
//     a point of the disk, the transmittance by ratio tracking, weight 1 / (m q); over a
//     flight this estimates int T(0, t) f T_sun dt by Campbell's theorem, so the real
//     collision a flight ends in gets no second estimate; in clear air inside a cloud
//     layer's band q is small, in cloud and in the air bands it is 1); (B) a path leaving
//     a real scattering in a direction inside the disk and escaping through the top;
//   - sun-guided copies (the droplets' forward peak, g_HG ~ 0.99 and ~0.5 deg wide, makes
//     (A) heavy-tailed: a path whose direction happens to lie within the peak about the
//     sun multiplies the sun by p ~ 1e3 /sr; detector-directional importance sampling of
//     Buras & Mayer 2011, JQSRT 112, 434, turned towards the sun): at a real scattering
//     (in cloud, or in air below the clouds' top; ground bounces below), with probability
//     sun_guiding, a copy of the path is made whose
//     direction is drawn from a Henyey-Greenstein lobe h about the sun (g = the largest
//     cloud g_HG). Path and copy are the two samples of a multi-sample MIS of everything
//     arriving at the vertex (balance heuristic, densities p and sun_guiding h): both
//     continue with weight beta f / (s (p + sun_guiding h)), which is <= the plain
//     weight, so nothing grows over the thousands of scatterings inside a thick cloud.
//     Copies are paths like the camera's (they make copies too). A cloud vertex guides
//     only where the sun may be seen: its cell's cloud optical depth towards the sun
//     (SunDepthCache, a deterministic function of the position) is below guide_depth;
//     an air vertex only below the highest cloud top; and only until the camera path has
//     made max_copies (a rule of the path's history).
//     Both are functions of the vertex and the path's history, which the MIS weights may
//     depend on, so neither biases the estimate. (B) counts both directions' densities;
//     measured on a slab of optical depth 4 (sun 60 deg, view up from below) the
//     per-path standard deviation falls from 2.6 to 0.21 at 1.8x the work;
//   - camera rays multiply the air's part of the majorant by camera_air_scale: more
//     tentative collisions, hence more next-event estimates of the thin sky; at twilight
//     every flight's air majorant is at least twilight_air_floor and q at least
//     floor / m, so the sunlit upper air, the only light then, is sampled on every ray
//     that crosses it (any majorant >= the extinction keeps delta tracking unbiased;
//     Novak et al. 2018, §4);
//   - sun transmittance by ratio tracking (Novak et al. 2018, §4.3), 0 when the ray hits
//     the ground (the planet's shadow, found before any tracking), with Russian roulette
//     below shadow_roulette;
//   - ground: Lambertian; next event albedo / pi (n . w_sun) L_sun T_sun over the disk
//     (MIS against the bounce), then a cosine-weighted bounce with beta *= albedo, and where
//     the sun is above the ground's horizon and not buried in cloud a sun-guided copy as at
//     a medium vertex (both weighted albedo (cos / pi) / (cos / pi + sun_guiding h));
//   - escape through the top: beta times the sky radiance; an unscattered camera ray
//     inside the disk adds beta L_sun (the disk the model draws);
//   - Russian roulette on the path once its importance, max_c beta_c times
//     max(1, 4 pi h(w . w_sun)), falls below path_roulette (a path heading into the sun's
//     forward peak is kept at its small weight rather than boosted).
// Light reaching the camera after k scattering events (ground bounces included) is
// "order k"; max_order limits the orders counted (1 = single scattering only).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/model/slab_monte_carlo.h"  // model::Pcg32
#include "renderer/truth/sun_depth_cache.h"
#include "renderer/truth/truth_world.h"

namespace cloudsvc::truth {

// Revision of the estimator's sampling rules (not of its settings): raised whenever a change
// makes the same settings and seed draw other paths, so that caches of truth images
// (bench/image_cache.h) are recomputed.
inline constexpr int kEstimatorRevision = 4;  // 4: the twilight air floor; shadow rays into the planet end before tracking

struct TracerSettings {
  double camera_air_scale = 8.0;  // >= 1
  double nee_boost = 16.0;        // > 0
  // Twilight (the sun below the horizon of the frame's +z axis, the point under the camera
  // in a scene world): the least air majorant on a path's flights, 1/m, and next events
  // at every tentative collision there. Only the thin upper air sees the sun then, where
  // the air's own majorant would draw a tentative collision on ~1 % of the rays; at this
  // floor a ray through it draws one every 5 km (0 = off).
  double twilight_air_floor = 2e-4;
  double sun_guiding = 0.3;       // probability of a sun-guided copy at a scattering that may guide, [0, 1)
  int max_copies = 1024;          // per camera path; beyond it no vertex makes copies (a bound on the work)
  // Copies only where the cloud optical depth towards the sun (SunDepthCache, cells of
  // guide_cell_m) is below guide_depth; infinity = everywhere.
  double guide_depth = 8.0;
  double guide_cell_m = 50.0;
  // Russian roulette thresholds on max_c of the weight: paths, and the transmittance of
  // shadow rays.
  double path_roulette = 0.05;
  double shadow_roulette = 0.1;
  int max_order = 1 << 30;
  // Safety cap of tentative collisions per path (a path beyond it is dropped and counted
  // as lost: a bias the stats report; none expected: a path through 100 km of cloud at a
  // majorant of 0.3 /m has ~3e4).
  std::uint64_t max_collisions = 100'000'000;
};

// Where a path's radiance comes from: each contribution added to a path's estimate is one
// of these (for diagnosis of the estimator's variance: bench/truth_scene_probe.cpp).
enum class Contribution {
  NextEventThin,        // next event at a tentative collision drawn with probability q < 1
  NextEventCloudGuided, // ... with q = 1 in cloud, where a guided copy may be made
  NextEventCloudPlain,  // ... with q = 1 in cloud, no copy possible (max_copies spent; or a collimated sun)
  NextEventAir,         // ... with q = 1 in cloud-free air
  SunEscape,            // (B): a path leaving a vertex into the sun's disk
  SkyEscape,            // night sky through the top
  GroundNextEvent,      // the sun at a ground bounce
  SunDisk,              // the disk seen by an unscattered camera ray
  Count
};
inline constexpr const char* kContributionNames[] = {"next event, q < 1", "next event, cloud, guided",
                                                     "next event, cloud, no copies left", "next event, air",
                                                     "sun escape (B)", "sky escape", "ground next event",
                                                     "sun disk"};
// Sum, sum of squares (of the channel mean) and largest of one kind's contributions.
struct ContributionStats {
  double sum = 0.0, sum2 = 0.0, max = 0.0;
  std::uint64_t count = 0;  // non-zero contributions
  void add(double v) {
    sum += v;
    sum2 += v * v;
    max = v > max ? v : max;
    ++count;
  }
  void add(const ContributionStats& o) {
    sum += o.sum;
    sum2 += o.sum2;
    max = o.max > max ? o.max : max;
    count += o.count;
  }
};

// Work and health counters of a set of paths (summed per pixel, then per image).
struct TracerCounters {
  std::uint64_t density_evals = 0;        // medium evaluations (TruthMedium::at calls)
  std::uint64_t majorant_violations = 0;  // points where an extinction exceeded the majorant
  std::uint64_t lost_paths = 0;           // paths dropped at max_collisions
  std::uint64_t scattering_events = 0;    // real collisions + ground bounces
  std::uint64_t camera_paths = 0;         // radiance() calls
  std::uint64_t path_collisions = 0;      // tentative collisions of camera paths and their copies (not shadow rays)
  std::uint64_t copies = 0;               // sun-guided copies made
  ContributionStats contributions[static_cast<int>(Contribution::Count)];

  void add(const TracerCounters& o) {
    density_evals += o.density_evals;
    camera_paths += o.camera_paths;
    path_collisions += o.path_collisions;
    copies += o.copies;
    for (int k = 0; k < static_cast<int>(Contribution::Count); ++k) contributions[k].add(o.contributions[k]);
    majorant_violations += o.majorant_violations;
    lost_paths += o.lost_paths;
    scattering_events += o.scattering_events;
  }
};

class PathTracer {
 public:
  // sun_depth: made from world with cell settings.guide_cell_m and cap settings.guide_depth
  // (make_sun_depth_cache); shared by every tracer of the world.
  PathTracer(const TruthWorld& world, const TracerSettings& settings, const SunDepthCache& sun_depth,
             model::Pcg32& rng, TracerCounters& counters);

  // One estimate of the radiance arriving at x from direction -w (i.e. seen looking
  // along w), x in the centred frame, w unit.
  glm::dvec3 radiance(const glm::dvec3& x, const glm::dvec3& w);

  // One unbiased estimate of the transmittance of the cloud components alone from x along
  // w to the ground or the top (ratio tracking): the cloud opacity of a pixel is 1 minus
  // its mean.
  double cloud_transmittance(const glm::dvec3& x, const glm::dvec3& w);

  // One unbiased estimate of the transmittance (rgb) from x along w to the top (0 if the
  // ray hits the ground), by ratio tracking.
  glm::dvec3 transmittance(const glm::dvec3& x, const glm::dvec3& w);

 private:
  // A real scattering vertex (what the MIS weights of the paths leaving it need).
  struct Vertex {
    glm::dvec3 y{0.0}, w_in{0.0}, beta{1.0};  // position, arriving direction, weight before it
    MediumPoint medium;
    double s_bar = 0.0;        // <beta sigma_s> / <beta>, 1/m
    double nee_density = 0.0;  // density of the next-event sample: m q / Omega, 1/(m sr)
    double guiding = 0.0;      // sun_guiding if a copy may be made here, else 0
  };
  enum class VertexKind { None, Medium, Ground };
  // A path (the camera's or a guided copy) between flights.
  struct PathState {
    glm::dvec3 x{0.0}, w{0.0}, beta{1.0};
    int order = 0;
    VertexKind vertex = VertexKind::None;  // of the last scattering
    Vertex last;                   // of the last medium scattering; after a ground bounce only its guiding
    glm::dvec3 last_normal{0.0};   // of the last ground bounce
  };
  glm::dvec3 trace(PathState s, std::vector<PathState>& copies, std::uint64_t& collisions);
  // Weights of a sample leaving vertex v in direction w_out.
  double direction_density(const Vertex& v, const glm::dvec3& w_out) const;  // p + guiding h, 1/sr
  double escape_weight(const Vertex& v, const glm::dvec3& w_out) const;

  // Adds contribution c of kind k to L and to the counters.
  void add(glm::dvec3& L, Contribution k, const glm::dvec3& c) {
    const double v = (c.x + c.y + c.z) / 3.0;
    if (v > 0.0) counters_.contributions[static_cast<int>(k)].add(v);
    L += c;
  }
  double uniform() { return rng_.uniform(); }
  double exponential() { return -std::log1p(-uniform()); }
  void medium_at(const glm::dvec3& y, double altitude_m, double majorant, MediumPoint& m);
  glm::dvec3 scattering_kernel(const MediumPoint& m, double nu) const;  // sum_k sigma_k p_k(nu), 1/(m sr)
  double phase_pdf(const MediumPoint& m, const glm::dvec3& beta, double nu) const;  // 1/sr
  // The density cloud component i's directions are drawn with (1/sr): its fit, or its Mie
  // table's channels averaged with the path throughput beta as weights (a channel is picked
  // in proportion to beta, pick_channel, and its p sampled), so the channel weights
  // p_c / density keep the sum of beta: no channel's throughput runs away over many
  // scatterings.
  double cloud_sampling_phase(int i, const glm::dvec3& beta, double nu) const;
  int pick_channel(const glm::dvec3& beta);
  glm::dvec3 sample_phase(const MediumPoint& m, const glm::dvec3& beta, double s_bar, const glm::dvec3& w);
  glm::dvec3 sample_sun_direction();  // uniform over the sun's disk
  bool copies_allowed() const;                 // a disk sun, cloud phases, copies left
  bool meets_ground(const glm::dvec3& x, const glm::dvec3& w) const;  // the ray x + t w, t > 0, hits the ground sphere
  bool sun_shallow(const glm::dvec3& y) const;  // the sun above y's horizon and y's cloud depth towards it < guide_depth
  double guiding_at(const glm::dvec3& y, double altitude_m, const MediumPoint& m) const;
  // Next-event estimate (A) at a tentative collision (the caller has drawn it with
  // probability q): the sun's contribution scattered at y towards -w, MIS-weighted
  // against (B) when the path continues from a real collision there (a guided copy does
  // not: weight 1).
  glm::dvec3 sun_at_collision(const glm::dvec3& y, const glm::dvec3& w, const MediumPoint& m, double majorant,
                              double q, double guiding, const glm::dvec3& beta, bool path_continues);
  // ... at a ground point with normal n (MIS against the cosine-weighted bounce's escape).
  glm::dvec3 sun_at_ground(const glm::dvec3& n, const glm::dvec3& y, double guiding, const glm::dvec3& beta,
                           bool path_continues);
  // Sun guiding at a ground point y with normal n (the sun above its horizon, not buried in
  // cloud), and the density of the directions leaving it: cos / pi + guiding h, 1/sr.
  double ground_guiding_at(const glm::dvec3& n, const glm::dvec3& y) const;
  double ground_density(const glm::dvec3& n, double guiding, const glm::dvec3& w_out) const;

  const TruthWorld& world_;
  const TracerSettings& settings_;
  const SunDepthCache& sun_depth_;
  model::Pcg32& rng_;
  TracerCounters& counters_;
  bool sun_on_ = false, disk_ = false;
  glm::dvec3 sun_radiance_{0.0};  // E_sun / Omega
  double sun_cos_radius_ = 1.0, sun_solid_angle_ = 0.0;
  double guide_g_ = 0.0;
  double air_floor_ = 0.0;  // twilight_air_floor at twilight, else 0
  double cloud_top_m_ = -std::numeric_limits<double>::infinity();  // top of the highest band with a cloud part in its majorant
  int copies_made_ = 0;  // by the current camera path
};

// Mean and standard error of `paths` radiance estimates from x along w, in chunks of
// kPathsPerChunk paths, chunk k drawing from model::chunk_stream(seed, k), summed in
// chunk order on `threads` threads (0 = all cores): the result does not depend on the
// thread count. For tests and single-direction measurements.
// The SunDepthCache a PathTracer of world with these settings takes.
SunDepthCache make_sun_depth_cache(const TruthWorld& world, const TracerSettings& settings);

struct RadianceEstimate {
  glm::dvec3 mean{0.0}, std_error{0.0};
  TracerCounters counters;
};
inline constexpr long long kPathsPerChunk = 256;
RadianceEstimate estimate_radiance(const TruthWorld& world, const TracerSettings& settings, const glm::dvec3& x,
                                   const glm::dvec3& w, long long paths, std::uint64_t seed, int threads = 0);

}  // namespace cloudsvc::truth
