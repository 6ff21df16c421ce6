// Monte Carlo slab radiative transfer (see slab_monte_carlo.h).
#include "renderer/model/slab_monte_carlo.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "common/parallel_for.h"
#include "renderer/model/droplet_optics.h"

namespace cloudsvc::model {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegToRad = kPi / 180.0;

// SplitMix64 (Steele, Lea & Flood 2014): decorrelates the per-chunk PCG seeds.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The medium seen by the tracker. Homogeneous here; a heterogeneous sigma_t(z) would only
// change sigma_t(), majorant() (any bound >= sigma_t on the segment) and optical_depth()
// (or replace the analytic optical depth of the next-event estimate by ratio tracking).
struct HomogeneousSlabMedium {
  double sigma = 0.0;  // 1/m
  double H = 0.0;      // m
  double sigma_t(double z) const { return (z > 0.0 && z < H) ? sigma : 0.0; }
  double majorant() const { return sigma; }
  double optical_depth(double z0, double z1) const { return sigma * std::fabs(z1 - z0); }
};

// Layout of the per-history estimator vector.
struct Layout {
  int nv = 0;
  static constexpr int kR = 0, kT = 1, kTdiff = 2, kTdir = 3, kRT = 4, kFirstView = 5;
  int top(int k) const { return kFirstView + k; }
  int top_single(int k) const { return kFirstView + nv + k; }
  int bottom(int k) const { return kFirstView + 2 * nv + k; }
  int bottom_single(int k) const { return kFirstView + 3 * nv + k; }
  int size() const { return kFirstView + 4 * nv; }
};

struct Context {
  HomogeneousSlabMedium medium;
  JdDParams phase;
  glm::dvec3 sun;  // towards the sun
  double mu0 = 1.0;
  std::vector<glm::dvec3> top_dirs, bottom_dirs;  // travel directions of the escaping light
  std::vector<double> view_mu;              // |cos view zenith| > 0
  Layout layout;
  std::uint64_t max_collisions = 0;
  double nee_max_tau = 40.0;
  double ddis_probability = 0.0;
  double ddis_max_tau = 0.0;
  double roulette_below = 0.0;
};

struct ChunkSums {
  std::vector<double> sum, sum_sq;
  std::uint64_t photons = 0, lost = 0, collisions = 0;
};

// A photon (or a DDIS copy of one) in flight.
struct PathState {
  double z = 0.0;
  glm::dvec3 d;
  double weight = 1.0;
  std::uint64_t order = 0;  // real collisions so far (scattering order)
};

// Mean of the phase function over the DDIS target directions at direction w (sr^-1).
double target_pdf(const Context& c, const glm::dvec3* targets, int n_targets, const glm::dvec3& w) {
  double q = 0.0;
  for (int k = 0; k < n_targets; ++k) q += jdd_phase(glm::dot(targets[k], w), c.phase);
  return q / n_targets;
}

// One photon history (the photon and its DDIS copies): adds its contribution to each estimator
// to `x` (zeroed by the caller). Returns the number of real collisions; sets `lost` if
// it exceeded the cap.
std::uint64_t trace_photon(const Context& c, Pcg32& rng, std::vector<double>& x, bool& lost) {
  const HomogeneousSlabMedium& m = c.medium;
  const Layout& L = c.layout;
  const int nv = L.nv;
  std::vector<PathState> stack;
  stack.push_back({m.H, {-c.sun.x, -c.sun.y, -c.sun.z}, 1.0, 0});  // enters at the top
  std::vector<glm::dvec3> targets(2 * nv);
  std::uint64_t collisions = 0;
  lost = false;
  while (!stack.empty()) {
    PathState ps = stack.back();
    stack.pop_back();
    double& z = ps.z;
    glm::dvec3& d = ps.d;
    for (;;) {
      // Distance to the slab boundary along d.
      const double t_exit = d.z < 0.0 ? z / -d.z : d.z > 0.0 ? (m.H - z) / d.z
                                                             : std::numeric_limits<double>::infinity();
      // Delta tracking: tentative collisions at the majorant rate, each real with
      // probability sigma_t / majorant, otherwise a null collision (continue the flight).
      const double maj = m.majorant();
      double t = 0.0;
      bool real = false;
      for (;;) {
        t += -std::log(1.0 - rng.uniform()) / maj;
        if (t >= t_exit) break;
        const double s = m.sigma_t(z + t * d.z);
        if (s >= maj || rng.uniform() * maj < s) {
          real = true;
          break;
        }
      }
      if (!real) {  // escapes
        if (d.z < 0.0) {
          x[Layout::kT] += ps.weight;
          x[ps.order == 0 ? Layout::kTdir : Layout::kTdiff] += ps.weight;
        } else {
          x[Layout::kR] += ps.weight;
        }
        x[Layout::kRT] += ps.weight;
        break;
      }
      z = std::clamp(z + t * d.z, 0.0, m.H);
      ++ps.order;
      if (++collisions > c.max_collisions) {
        lost = true;
        return collisions;
      }
      // Next-event estimate towards each view direction at the top and at the bottom:
      // L/F += w · mu0 · p(d · w_v) · e^{-tau(z -> boundary) / mu_v} / mu_v (mu0 applied
      // when the history is finished). A photon carries flux mu0·F/N per unit area; a
      // collision re-emits intensity p per unit power; 1/mu_v converts the horizontal
      // collision density to the slant path of the view ray.
      const double tau_up = m.optical_depth(z, m.H), tau_down = m.optical_depth(0.0, z);
      int n_targets = 0;
      for (int k = 0; k < nv; ++k) {
        const double mu = c.view_mu[k];
        const double tu = tau_up / mu;
        if (tu < c.nee_max_tau) {
          const double v = ps.weight * jdd_phase(glm::dot(d, c.top_dirs[k]), c.phase) * std::exp(-tu) / mu;
          x[L.top(k)] += v;
          if (ps.order == 1) x[L.top_single(k)] += v;
        }
        const double td = tau_down / mu;
        if (td < c.nee_max_tau) {
          const double v = ps.weight * jdd_phase(glm::dot(d, c.bottom_dirs[k]), c.phase) * std::exp(-td) / mu;
          x[L.bottom(k)] += v;
          if (ps.order == 1) x[L.bottom_single(k)] += v;
        }
        if (tu < c.ddis_max_tau) targets[n_targets++] = c.top_dirs[k];
        if (td < c.ddis_max_tau) targets[n_targets++] = c.bottom_dirs[k];
      }
      // Russian roulette of low weights, after this collision's next-event estimate
      // (which used the exact weight): a low-weight DDIS sample thus makes its first,
      // most important estimate at full resolution before it may be dropped.
      if (ps.weight < c.roulette_below) {
        const double survive = 2.0 * c.roulette_below;
        if (rng.uniform() * survive >= ps.weight) break;
        ps.weight = survive;
      }
      // Scatter (albedo 1: no absorption). The continuing photon samples the phase about
      // d. DDIS as multi-sample MIS (Veach 1997 ch. 9, balance heuristic): with
      // probability eps a copy is spawned whose direction is sampled from the mean of the
      // phase peaks about the reachable view directions (pdf q); every sample then
      // carries p / (p + eps q) <= 1, so weights never grow and the sum stays unbiased.
      const glm::dvec3 nd = scatter_direction(d, sample_jdd_cos_theta(c.phase, rng), 2.0 * kPi * rng.uniform());
      if (n_targets > 0 && c.ddis_probability > 0.0) {
        const double eps = c.ddis_probability;
        if (rng.uniform() < eps) {
          const int k = std::min(static_cast<int>(rng.uniform() * n_targets), n_targets - 1);
          PathState copy = ps;
          copy.d = scatter_direction(targets[k], sample_jdd_cos_theta(c.phase, rng), 2.0 * kPi * rng.uniform());
          const double pc = jdd_phase(glm::dot(d, copy.d), c.phase);
          copy.weight *= pc / (pc + eps * target_pdf(c, targets.data(), n_targets, copy.d));
          if (copy.weight > 0.0) stack.push_back(copy);
        }
        const double pm = jdd_phase(glm::dot(d, nd), c.phase);
        ps.weight *= pm / (pm + eps * target_pdf(c, targets.data(), n_targets, nd));
      }
      d = nd;
    }
  }
  return collisions;
}

void run_chunk(const Context& c, std::uint64_t seed, int chunk, std::uint64_t photons, ChunkSums& out) {
  const int n = c.layout.size();
  out.sum.assign(n, 0.0);
  out.sum_sq.assign(n, 0.0);
  Pcg32 rng = chunk_stream(seed, static_cast<std::uint64_t>(chunk));
  std::vector<double> x(n);
  for (std::uint64_t i = 0; i < photons; ++i) {
    std::fill(x.begin(), x.end(), 0.0);
    bool lost = false;
    out.collisions += trace_photon(c, rng, x, lost);
    if (lost) {
      ++out.lost;  // contributes zero to every estimator (R + T < 1 shows it)
      std::fill(x.begin(), x.end(), 0.0);
    }
    for (int k = Layout::kFirstView; k < n; ++k) x[k] *= c.mu0;
    for (int k = 0; k < n; ++k) {
      out.sum[k] += x[k];
      out.sum_sq[k] += x[k] * x[k];
    }
  }
  out.photons = photons;
}

Estimate make_estimate(double sum, double sum_sq, double n) {
  Estimate e;
  e.mean = sum / n;
  const double var = n > 1.0 ? std::max(0.0, (sum_sq - sum * e.mean) / (n - 1.0)) : 0.0;
  e.std_error = std::sqrt(var / n);
  return e;
}

}  // namespace

SlabSpec slab_from_optical_depth(double tau, double sun_zenith_deg, double droplet_diameter_um) {
  SlabSpec s;
  s.sigma_t_per_m = cloud_extinction_per_m(droplet_diameter_um);
  s.thickness_m = tau / s.sigma_t_per_m;
  s.sun_zenith_deg = sun_zenith_deg;
  s.droplet_diameter_um = droplet_diameter_um;
  return s;
}

glm::dvec3 view_travel_direction(const ViewDirection& v, bool top) {
  const double th = v.zenith_deg * kDegToRad, ph = v.rel_azimuth_deg * kDegToRad;
  const double st = std::sin(th), ct = std::cos(th);
  return {st * std::cos(ph), st * std::sin(ph), top ? ct : -ct};
}

glm::dvec3 sun_direction(double sun_zenith_deg) {
  const double th = sun_zenith_deg * kDegToRad;
  return {std::sin(th), 0.0, std::cos(th)};
}

// n = sin_t cos(phi) t1 + sin_t sin(phi) t2 + cos_t d with (t1, t2, d) the branchless
// orthonormal basis of Duff et al. 2017 ("Building an Orthonormal Basis, Revisited",
// JCGT 6(1)): exact for every d, also within 1e-3 rad of the poles, where the
// direction-cosine update of MCML needs a special case that only approximates d as ±z.
glm::dvec3 scatter_direction(const glm::dvec3& d, double cos_t, double phi) {
  const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  const double cp = std::cos(phi) * sin_t, sp = std::sin(phi) * sin_t;
  const double sign = std::copysign(1.0, d.z);
  const double a = -1.0 / (sign + d.z);
  const double b = d.x * d.y * a;
  const glm::dvec3 t1{1.0 + sign * d.x * d.x * a, sign * b, -sign * d.x};
  const glm::dvec3 t2{b, sign + d.y * d.y * a, -d.y};
  const glm::dvec3 n{cp * t1.x + sp * t2.x + cos_t * d.x, cp * t1.y + sp * t2.y + cos_t * d.y,
               cp * t1.z + sp * t2.z + cos_t * d.z};
  const double inv = 1.0 / std::sqrt(glm::dot(n, n));  // stop round-off drift over many bounces
  return {n.x * inv, n.y * inv, n.z * inv};
}

// ---- PCG32: pcg32_srandom_r / pcg32_random_r of the reference implementation ----
Pcg32::Pcg32(std::uint64_t seed, std::uint64_t stream) : inc_((stream << 1u) | 1u) {
  next_u32();
  state_ += seed;
  next_u32();
}

std::uint32_t Pcg32::next_u32() {
  const std::uint64_t old = state_;
  state_ = old * 6364136223846793005ull + inc_;
  const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
  const auto rot = static_cast<std::uint32_t>(old >> 59u);
  return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

Pcg32 chunk_stream(std::uint64_t seed, std::uint64_t chunk) {
  return Pcg32(splitmix64(seed ^ splitmix64(chunk + 1)), chunk);
}

double Pcg32::uniform() {
  const std::uint64_t hi = next_u32() >> 5;  // 27 bits
  const std::uint64_t lo = next_u32() >> 6;  // 26 bits
  return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
}

// HG inverse CDF (e.g. pbrt-v4 §11.3.1), written for 1 - cos: with
// s = (1 - g^2) / (1 - g + 2 g u), cos = (1 + g^2 - s^2) / (2g), and
//   1 - cos = (1 - g)(1 - u)(s + 1 - g) / (1 - g + 2 g u),
// which keeps the forward peak (1 - cos ~ (1 - g)^2) free of cancellation.
double sample_hg_cos_theta(double g, double u) {
  if (std::fabs(g) < 1e-6) return 1.0 - 2.0 * u;
  const double den = 1.0 - g + 2.0 * g * u;
  const double s = (1.0 - g) * (1.0 + g) / den;
  const double one_minus_cos = (1.0 - g) * (1.0 - u) * (s + 1.0 - g) / den;
  return std::clamp(1.0 - one_minus_cos, -1.0, 1.0);
}

double sample_draine_cos_theta(double g, double alpha, Pcg32& rng) {
  // p_D ∝ p_HG(mu; g) (1 + alpha mu^2); (1 + alpha mu^2) <= 1 + alpha.
  for (;;) {
    const double mu = sample_hg_cos_theta(g, rng.uniform());
    if (rng.uniform() * (1.0 + alpha) <= 1.0 + alpha * mu * mu) return mu;
  }
}

double sample_jdd_cos_theta(const JdDParams& p, Pcg32& rng) {
  if (rng.uniform() >= p.w_d) return sample_hg_cos_theta(p.g_hg, rng.uniform());
  return sample_draine_cos_theta(p.g_d, p.alpha, rng);
}

SlabMcResult run_slab_monte_carlo(const SlabSpec& slab, const SlabMcOptions& options) {
  if (!(slab.sigma_t_per_m > 0.0) || !(slab.thickness_m > 0.0))
    throw std::invalid_argument("slab needs sigma_t > 0 and thickness > 0");
  if (!(slab.sun_zenith_deg >= 0.0 && slab.sun_zenith_deg < 89.0))
    throw std::invalid_argument("sun zenith must be in [0, 89) degrees");
  for (const ViewDirection& v : options.views)
    if (!(v.zenith_deg >= 0.0 && v.zenith_deg < 89.0))
      throw std::invalid_argument("view zenith must be in [0, 89) degrees");
  const auto t_start = std::chrono::steady_clock::now();

  Context c;
  c.medium = {slab.sigma_t_per_m, slab.thickness_m};
  c.phase = jdd_params(slab.droplet_diameter_um);
  c.sun = sun_direction(slab.sun_zenith_deg);
  c.mu0 = c.sun.z;
  c.layout.nv = static_cast<int>(options.views.size());
  for (const ViewDirection& v : options.views) {
    c.top_dirs.push_back(view_travel_direction(v, true));
    c.bottom_dirs.push_back(view_travel_direction(v, false));
    c.view_mu.push_back(std::cos(v.zenith_deg * kDegToRad));
  }
  c.max_collisions = options.max_collisions;
  c.nee_max_tau = options.nee_max_optical_depth;
  c.ddis_probability = std::clamp(options.ddis_probability, 0.0, 0.9);
  c.ddis_max_tau = options.ddis_max_optical_depth;
  c.roulette_below = std::max(0.0, options.weight_roulette_below);

  const int chunks = std::max(1, options.chunks);
  std::vector<ChunkSums> sums(chunks);
  parallel_for(chunks, options.threads, [&](int k) {
    const std::uint64_t n = options.photons / chunks + (static_cast<std::uint64_t>(k) < options.photons % chunks ? 1 : 0);
    run_chunk(c, options.seed, k, n, sums[k]);
  });

  // Merge in chunk order (deterministic summation).
  const int n_est = c.layout.size();
  std::vector<double> sum(n_est, 0.0), sum_sq(n_est, 0.0);
  SlabMcResult r;
  std::uint64_t collisions = 0;
  for (const ChunkSums& s : sums) {
    for (int k = 0; k < n_est; ++k) {
      sum[k] += s.sum[k];
      sum_sq[k] += s.sum_sq[k];
    }
    r.photons += s.photons;
    r.lost_photons += s.lost;
    collisions += s.collisions;
  }
  const double n = static_cast<double>(std::max<std::uint64_t>(r.photons, 1));
  auto est = [&](int k) { return make_estimate(sum[k], sum_sq[k], n); };
  r.reflected = est(Layout::kR);
  r.transmitted = est(Layout::kT);
  r.transmitted_diffuse = est(Layout::kTdiff);
  r.transmitted_direct = est(Layout::kTdir);
  r.reflected_plus_transmitted = est(Layout::kRT);
  for (int k = 0; k < c.layout.nv; ++k) {
    r.radiance_top.push_back(est(c.layout.top(k)));
    r.radiance_top_single.push_back(est(c.layout.top_single(k)));
    r.radiance_bottom.push_back(est(c.layout.bottom(k)));
    r.radiance_bottom_single.push_back(est(c.layout.bottom_single(k)));
  }
  r.mean_collisions = static_cast<double>(collisions) / n;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return r;
}

}  // namespace cloudsvc::model
