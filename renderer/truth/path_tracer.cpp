// Path tracer of the ground truth (see path_tracer.h).
#include "renderer/truth/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "common/parallel_for.h"
#include "renderer/reference/atmosphere_monte_carlo.h"  // Rayleigh / Cornette-Shanks phases and samplers
#include "renderer/truth/band_walker.h"

namespace cloudsvc::truth {

namespace {

constexpr double kPi = std::numbers::pi;

double mean3(const glm::dvec3& v) { return (v.x + v.y + v.z) / 3.0; }
double max3(const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); }

// Scattering components of a MediumPoint: 0 Rayleigh, 1 aerosol, 2 + i cloud layer i.
constexpr int kRayleigh = 0, kAerosol = 1, kFirstCloud = 2;

}  // namespace

SunDepthCache make_sun_depth_cache(const TruthWorld& world, const TracerSettings& settings) {
  return SunDepthCache(world, settings.guide_cell_m, std::isfinite(settings.guide_depth) ? settings.guide_depth : 1.0);
}

PathTracer::PathTracer(const TruthWorld& world, const TracerSettings& settings, const SunDepthCache& sun_depth,
                       model::Pcg32& rng, TracerCounters& counters)
    : world_(world), settings_(settings), sun_depth_(sun_depth), rng_(rng), counters_(counters) {
  sun_on_ = max3(world.sun_irradiance) > 0.0;
  sun_cos_radius_ = std::cos(world.sun_angular_radius_rad);
  sun_solid_angle_ = 2.0 * kPi * (1.0 - sun_cos_radius_);
  disk_ = sun_on_ && sun_solid_angle_ > 0.0;
  if (disk_) sun_radiance_ = world.sun_irradiance / sun_solid_angle_;
  for (const model::JdDParams& p : world.cloud_phase) guide_g_ = std::max(guide_g_, p.g_hg);
  if (sun_on_ && world.sun.z < 0.0) air_floor_ = settings.twilight_air_floor;
  for (std::size_t b = 0; b < world.band_majorant.size(); ++b)
    if (world.band_majorant[b] > world.band_air_majorant[b]) cloud_top_m_ = world.band_edges[b + 1];
}

void PathTracer::medium_at(const glm::dvec3& y, double altitude_m, double majorant, MediumPoint& m) {
  m = MediumPoint{};
  world_.medium->at(y, altitude_m, m);
  ++counters_.density_evals;
  if (max3(m.extinction()) > majorant * (1.0 + 1e-9)) ++counters_.majorant_violations;
}

glm::dvec3 PathTracer::scattering_kernel(const MediumPoint& m, double nu) const {
  glm::dvec3 f = m.rayleigh * reference::atmo::rayleigh_phase(nu);
  double grey = m.aerosol > 0.0 ? m.aerosol * reference::mc::cornette_shanks_phase(nu, world_.aerosol_g) : 0.0;
  for (int i = 0; i < kMaxCloudComponents; ++i) {
    const double s = m.cloud[static_cast<std::size_t>(i)];
    if (s <= 0.0) continue;
    if (const model::PhaseTable* mie = world_.cloud_mie[static_cast<std::size_t>(i)])
      f += s * mie->at_cos(nu);
    else
      grey += s * model::jdd_phase(nu, world_.cloud_phase[static_cast<std::size_t>(i)]);
  }
  return f + glm::dvec3(grey);
}

double PathTracer::cloud_sampling_phase(int i, const glm::dvec3& beta, double nu) const {
  const model::PhaseTable* mie = world_.cloud_mie[static_cast<std::size_t>(i)];
  return mie ? mean3(beta * mie->at_cos(nu)) / mean3(beta)
             : model::jdd_phase(nu, world_.cloud_phase[static_cast<std::size_t>(i)]);
}

double PathTracer::phase_pdf(const MediumPoint& m, const glm::dvec3& beta, double nu) const {
  const double b = mean3(beta);
  const double weight = mean3(beta * m.scattering());
  if (weight <= 0.0) return 0.0;
  double pdf = mean3(beta * m.rayleigh) * reference::atmo::rayleigh_phase(nu);
  if (m.aerosol > 0.0) pdf += b * m.aerosol * reference::mc::cornette_shanks_phase(nu, world_.aerosol_g);
  for (int i = 0; i < kMaxCloudComponents; ++i) {
    const double s = m.cloud[static_cast<std::size_t>(i)];
    if (s > 0.0) pdf += b * s * cloud_sampling_phase(i, beta, nu);
  }
  return pdf / weight;
}

glm::dvec3 PathTracer::sample_phase(const MediumPoint& m, const glm::dvec3& beta, double s_bar, const glm::dvec3& w) {
  // The component, in proportion to <beta sigma_k> (their sum is s_bar <beta>).
  const double b = mean3(beta);
  const double pick = uniform() * s_bar * b;
  double acc = mean3(beta * m.rayleigh);
  double cos_t = 0.0;
  if (pick < acc) {
    cos_t = reference::mc::sample_rayleigh_cos(uniform());
  } else {
    acc += b * m.aerosol;
    int cloud = -1;
    for (int i = 0; i < kMaxCloudComponents && pick >= acc; ++i) {
      const double s = m.cloud[static_cast<std::size_t>(i)];
      if (s <= 0.0) continue;
      acc += b * s;
      cloud = i;
    }
    if (cloud < 0)
      cos_t = reference::mc::sample_cornette_shanks_cos(world_.aerosol_g, rng_);
    else if (const model::PhaseTable* mie = world_.cloud_mie[static_cast<std::size_t>(cloud)])
      cos_t = mie->sample_cos(pick_channel(beta), [this] { return uniform(); });
    else
      cos_t = model::sample_jdd_cos_theta(world_.cloud_phase[static_cast<std::size_t>(cloud)], rng_);
  }
  return model::scatter_direction(w, cos_t, 2.0 * kPi * uniform());
}

int PathTracer::pick_channel(const glm::dvec3& beta) {
  const double u = uniform() * (beta.r + beta.g + beta.b);
  return u < beta.r ? 0 : (u < beta.r + beta.g ? 1 : 2);
}

glm::dvec3 PathTracer::sample_sun_direction() {
  const double cos_t = 1.0 - uniform() * (1.0 - sun_cos_radius_);
  return model::scatter_direction(world_.sun, cos_t, 2.0 * kPi * uniform());
}

bool PathTracer::copies_allowed() const {
  return disk_ && guide_g_ > 0.0 && settings_.sun_guiding > 0.0 && copies_made_ < settings_.max_copies;
}

bool PathTracer::meets_ground(const glm::dvec3& x, const glm::dvec3& w) const {
  const double ground_r = world_.radius_m + world_.ground_alt_m;
  const double xw = glm::dot(x, w);
  return xw < 0.0 && glm::dot(x, x) - xw * xw < ground_r * ground_r;
}

bool PathTracer::sun_shallow(const glm::dvec3& y) const {
  if (meets_ground(y, world_.sun)) return false;  // the planet's shadow (twilight): no cell needed
  return !std::isfinite(settings_.guide_depth) || sun_depth_.depth(y) < settings_.guide_depth;
}

double PathTracer::guiding_at(const glm::dvec3& y, double altitude_m, const MediumPoint& m) const {
  // A function of the vertex and of the path's history (the copies made so far), as the
  // MIS weights at a vertex may be: while the camera path has made fewer than max_copies
  // copies; in cloud where the sun is not buried under more than guide_depth of cloud or
  // behind the planet; in air below the highest cloud top where the sun is above the
  // planet's horizon (a path scattered there by air towards the sun may
  // meet cloud on its way, where the forward peak would multiply its next events; above
  // the clouds the sun's next event alone is smooth in the air's broad phase functions).
  if (!copies_allowed()) return 0.0;
  if (m.cloud_total() <= 0.0)
    return altitude_m < cloud_top_m_ && !meets_ground(y, world_.sun) ? settings_.sun_guiding : 0.0;
  return sun_shallow(y) ? settings_.sun_guiding : 0.0;
}

double PathTracer::ground_guiding_at(const glm::dvec3& n, const glm::dvec3& y) const {
  if (!copies_allowed() || glm::dot(n, world_.sun) <= 0.0 || max3(world_.ground_albedo) <= 0.0) return 0.0;
  return sun_shallow(y) ? settings_.sun_guiding : 0.0;
}

double PathTracer::direction_density(const Vertex& v, const glm::dvec3& w_out) const {
  const double p = phase_pdf(v.medium, v.beta, glm::dot(v.w_in, w_out));
  return v.guiding > 0.0 ? p + v.guiding * model::hg_phase(glm::dot(w_out, world_.sun), guide_g_) : p;
}

double PathTracer::escape_weight(const Vertex& v, const glm::dvec3& w_out) const {
  // Balance heuristic over (A) the next event at v and (B) the directions leaving v (the
  // path's and a guided copy's; both weights carry their MIS share already).
  const double phase = v.s_bar * direction_density(v, w_out);
  return phase / (phase + v.nee_density);
}

glm::dvec3 PathTracer::sun_at_collision(const glm::dvec3& y, const glm::dvec3& w, const MediumPoint& m,
                                        double majorant, double q, double guiding, const glm::dvec3& beta,
                                        bool path_continues) {
  const glm::dvec3 wl = disk_ ? sample_sun_direction() : world_.sun;
  const double nu = glm::dot(w, wl);
  double mis = 1.0;
  if (disk_ && path_continues) {
    Vertex here;
    here.w_in = w;
    here.beta = beta;
    here.medium = m;
    here.s_bar = mean3(beta * m.scattering()) / mean3(beta);
    here.guiding = guiding;
    const double light = majorant * q / sun_solid_angle_;
    mis = light / (light + here.s_bar * direction_density(here, wl));
  }
  return beta * world_.sun_irradiance * scattering_kernel(m, nu) * transmittance(y, wl) * (mis / (majorant * q));
}

double PathTracer::ground_density(const glm::dvec3& n, double guiding, const glm::dvec3& w_out) const {
  const double cosine = std::max(0.0, glm::dot(n, w_out)) / kPi;
  return guiding > 0.0 ? cosine + guiding * model::hg_phase(glm::dot(w_out, world_.sun), guide_g_) : cosine;
}

glm::dvec3 PathTracer::sun_at_ground(const glm::dvec3& n, const glm::dvec3& y, double guiding, const glm::dvec3& beta,
                                     bool path_continues) {
  const glm::dvec3 wl = disk_ ? sample_sun_direction() : world_.sun;
  const double mu = glm::dot(n, wl);
  if (mu <= 0.0) return glm::dvec3(0.0);
  const double mis = disk_ && path_continues
                         ? (1.0 / sun_solid_angle_) / (1.0 / sun_solid_angle_ + ground_density(n, guiding, wl))
                         : 1.0;
  return beta * world_.ground_albedo / kPi * world_.sun_irradiance * mu * transmittance(y, wl) * mis;
}

glm::dvec3 PathTracer::transmittance(const glm::dvec3& x, const glm::dvec3& w) {
  if (meets_ground(x, w)) return glm::dvec3(0.0);  // as the walk below would end, without tracking to it
  BandWalker walk(world_, x, w);
  glm::dvec3 T(1.0);
  MediumPoint m;
  double majorant = 0.0;
  for (;;) {
    const double t = walk.advance(exponential(), majorant);
    if (t == kInfinity) return walk.end() == BandWalker::End::Ground ? glm::dvec3(0.0) : T;
    const glm::dvec3 y = x + t * w;
    medium_at(y, glm::length(y) - world_.radius_m, majorant, m);
    T *= glm::max(glm::dvec3(0.0), 1.0 - m.extinction() / majorant);
    const double tmax = max3(T);
    if (tmax < settings_.shadow_roulette) {
      const double q = tmax / settings_.shadow_roulette;
      if (uniform() >= q) return glm::dvec3(0.0);
      T /= q;
    }
  }
}

double PathTracer::cloud_transmittance(const glm::dvec3& x, const glm::dvec3& w) {
  BandWalker walk(world_, x, w);
  double T = 1.0, majorant = 0.0;
  MediumPoint m;
  for (;;) {
    const double t = walk.advance(exponential(), majorant);
    if (t == kInfinity) return T;
    const glm::dvec3 y = x + t * w;
    medium_at(y, glm::length(y) - world_.radius_m, majorant, m);
    T *= std::max(0.0, 1.0 - m.cloud_total() / majorant);
    if (T < settings_.shadow_roulette) {
      const double q = T / settings_.shadow_roulette;
      if (uniform() >= q) return 0.0;
      T /= q;
    }
  }
}

glm::dvec3 PathTracer::radiance(const glm::dvec3& x0, const glm::dvec3& w0) {
  std::vector<PathState> copies;
  std::uint64_t collisions = 0;
  copies_made_ = 0;
  PathState camera;
  camera.x = x0;
  camera.w = w0;
  glm::dvec3 L = trace(camera, copies, collisions);
  while (!copies.empty() && collisions <= settings_.max_collisions) {
    const PathState copy = copies.back();
    copies.pop_back();
    L += trace(copy, copies, collisions);
  }
  ++counters_.camera_paths;
  counters_.path_collisions += collisions;
  counters_.copies += static_cast<std::uint64_t>(copies_made_);
  if (collisions > settings_.max_collisions) {
    ++counters_.lost_paths;
    return glm::dvec3(0.0);
  }
  return L;
}

glm::dvec3 PathTracer::trace(PathState s, std::vector<PathState>& copies, std::uint64_t& collisions) {
  glm::dvec3 L(0.0);
  MediumPoint m;
  for (;;) {
    BandWalker walk(world_, s.x, s.w, s.order == 0 ? settings_.camera_air_scale : 1.0, air_floor_);
    bool scattered = false;
    double majorant = 0.0;
    const bool continues = s.order + 1 < settings_.max_order;  // a real collision here is not the last
    for (;;) {
      const double t = walk.advance(exponential(), majorant);
      if (t == kInfinity) break;
      if (++collisions > settings_.max_collisions) return glm::dvec3(0.0);
      const glm::dvec3 y = s.x + t * s.w;
      const double altitude = glm::length(y) - world_.radius_m;
      medium_at(y, altitude, majorant, m);
      const glm::dvec3 scattering = m.scattering();
      const double s_max = max3(scattering);
      const double q =
          s_max > 0.0 ? std::min(1.0, std::max(settings_.nee_boost * s_max, air_floor_) / majorant) : 0.0;
      const double guiding = guiding_at(y, altitude, m);  // at this point, were it a real scattering
      if (sun_on_ && s.order + 1 <= settings_.max_order && q > 0.0 && (q >= 1.0 || uniform() < q)) {
        const Contribution kind = q < 1.0                 ? Contribution::NextEventThin
                                  : m.cloud_total() <= 0.0 ? Contribution::NextEventAir
                                  : guiding > 0.0          ? Contribution::NextEventCloudGuided
                                                           : Contribution::NextEventCloudPlain;
        add(L, kind, sun_at_collision(y, s.w, m, majorant, q, guiding, s.beta, continues));
      }
      // Spectral tracking: a real scattering, a null collision or absorption.
      const double b_mean = mean3(s.beta);
      const double s_bar = mean3(s.beta * scattering) / b_mean;  // 1/m
      const glm::dvec3 sigma_null = glm::max(glm::dvec3(0.0), majorant - m.extinction());
      const double null_rate = mean3(s.beta * sigma_null) / b_mean;
      const double u = uniform() * majorant;
      if (u < s_bar) {
        Vertex& v = s.last;
        v.y = y;
        v.w_in = s.w;
        v.beta = s.beta;
        v.medium = m;
        v.s_bar = s_bar;
        v.nee_density = disk_ ? majorant * q / sun_solid_angle_ : 0.0;
        v.guiding = guiding;
        s.vertex = VertexKind::Medium;
        ++counters_.scattering_events;
        if (++s.order >= settings_.max_order) return L;
        // The path's direction from the phase function; with probability v.guiding also a
        // copy's from the sun lobe; both weights f / (s_bar (p + guiding h)).
        const glm::dvec3 w_new = sample_phase(m, s.beta, s_bar, s.w);
        s.beta = v.beta * scattering_kernel(m, glm::dot(v.w_in, w_new)) / (s_bar * direction_density(v, w_new));
        if (v.guiding > 0.0 && uniform() < v.guiding) {
          ++copies_made_;
          PathState copy = s;
          copy.w = model::scatter_direction(world_.sun, model::sample_hg_cos_theta(guide_g_, uniform()),
                                            2.0 * kPi * uniform());
          copy.x = y;
          copy.beta = v.beta * scattering_kernel(m, glm::dot(v.w_in, copy.w)) / (s_bar * direction_density(v, copy.w));
          copies.push_back(copy);
        }
        s.w = w_new;
        s.x = y;
        scattered = true;
        break;
      }
      if (u < s_bar + null_rate) {
        s.beta *= sigma_null / null_rate;
        continue;
      }
      return L;  // absorbed
    }
    if (!scattered) {
      if (walk.end() == BandWalker::End::Top) {
        add(L, Contribution::SkyEscape, s.beta * world_.sky_radiance);
        if (disk_ && glm::dot(s.w, world_.sun) > sun_cos_radius_) {
          if (s.vertex == VertexKind::None) {
            add(L, Contribution::SunDisk, s.beta * sun_radiance_);  // the disk itself, seen by the camera
          } else if (s.vertex == VertexKind::Medium) {
            add(L, Contribution::SunEscape, s.beta * sun_radiance_ * escape_weight(s.last, s.w));
          } else {  // after a ground bounce: MIS against the ground's next event
            const double d = ground_density(s.last_normal, s.last.guiding, s.w);
            add(L, Contribution::SunEscape, s.beta * sun_radiance_ * (d / (d + 1.0 / sun_solid_angle_)));
          }
        }
        return L;
      }
      // The ground: lift the hit point 1 mm so the bounce starts above the sphere.
      const glm::dvec3 n = glm::normalize(s.x + walk.distance() * s.w);
      const glm::dvec3 y = n * (world_.radius_m + world_.ground_alt_m + 1e-3);
      // Sun-guided copies as at a medium vertex (the sun above the ground's horizon and not
      // buried in cloud): the cosine-weighted bounce and the copy's sun lobe are the two
      // samples of a multi-sample MIS, both weighted albedo (cos / pi) / (cos / pi + guiding h).
      const double guiding = ground_guiding_at(n, y);
      if (sun_on_ && s.order + 1 <= settings_.max_order)
        add(L, Contribution::GroundNextEvent, sun_at_ground(n, y, guiding, s.beta, continues));
      s.vertex = VertexKind::Ground;
      s.last_normal = n;
      s.last.guiding = guiding;
      const glm::dvec3 beta_in = s.beta;
      ++counters_.scattering_events;
      if (++s.order >= settings_.max_order || max3(beta_in * world_.ground_albedo) <= 0.0) return L;
      const double u1 = uniform();
      const glm::dvec3 w_new = model::scatter_direction(n, std::sqrt(u1), 2.0 * kPi * uniform());  // cosine-weighted
      const double cos_new = glm::dot(n, w_new) / kPi;
      s.beta = beta_in * world_.ground_albedo * (cos_new / ground_density(n, guiding, w_new));
      if (guiding > 0.0 && uniform() < guiding) {
        const glm::dvec3 wc = model::scatter_direction(world_.sun, model::sample_hg_cos_theta(guide_g_, uniform()),
                                                       2.0 * kPi * uniform());
        const double cos_c = glm::dot(n, wc) / kPi;
        if (cos_c > 0.0) {  // a lobe direction into the ground reflects nothing
          ++copies_made_;
          PathState copy = s;
          copy.w = wc;
          copy.x = y;
          copy.beta = beta_in * world_.ground_albedo * (cos_c / ground_density(n, guiding, wc));
          copies.push_back(copy);
        }
      }
      s.w = w_new;
      s.x = y;
    }
    // Russian roulette on the path's importance: its weight, times how much the forward
    // peak towards the sun would multiply its next event (4 pi h, h the sun lobe) when it
    // heads for the sun, so that a survivor's next events are never boosted into a spike.
    const double peak = guide_g_ > 0.0 && disk_ ? 4.0 * kPi * model::hg_phase(glm::dot(s.w, world_.sun), guide_g_) : 0.0;
    const double importance = max3(s.beta) * std::max(1.0, peak);
    if (importance < settings_.path_roulette) {
      const double q = importance / settings_.path_roulette;
      if (uniform() >= q) return L;
      s.beta /= q;
    }
  }
}

RadianceEstimate estimate_radiance(const TruthWorld& world, const TracerSettings& settings, const glm::dvec3& x,
                                   const glm::dvec3& w, long long paths, std::uint64_t seed, int threads) {
  const long long chunks = (paths + kPathsPerChunk - 1) / kPathsPerChunk;
  struct Sums {
    glm::dvec3 s{0.0}, s2{0.0};
    TracerCounters counters;
  };
  std::vector<Sums> sums(static_cast<std::size_t>(chunks));
  const SunDepthCache sun_depth = make_sun_depth_cache(world, settings);
  parallel_for(static_cast<int>(chunks), threads, [&](int k) {
    Sums& out = sums[static_cast<std::size_t>(k)];
    model::Pcg32 rng = model::chunk_stream(seed, static_cast<std::uint64_t>(k));
    PathTracer tracer(world, settings, sun_depth, rng, out.counters);
    const long long n = std::min(kPathsPerChunk, paths - k * kPathsPerChunk);
    for (long long i = 0; i < n; ++i) {
      const glm::dvec3 L = tracer.radiance(x, w);
      out.s += L;
      out.s2 += L * L;
    }
  });
  RadianceEstimate e;
  glm::dvec3 s(0.0), s2(0.0);
  for (const Sums& c : sums) {
    s += c.s;
    s2 += c.s2;
    e.counters.add(c.counters);
  }
  const double n = static_cast<double>(paths);
  e.mean = s / n;
  e.std_error = glm::sqrt(glm::max(glm::dvec3(0.0), (s2 - n * e.mean * e.mean) / (n - 1.0)) / n);
  return e;
}

}  // namespace cloudsvc::truth
