// Monte Carlo path tracer of the clear-sky atmosphere (see atmosphere_monte_carlo.h).
#include "renderer/reference/atmosphere_monte_carlo.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "common/parallel_for.h"

namespace cloudsvc::reference::mc {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGround = atmo::kBottomRadius;  // m
constexpr double kTop = atmo::kTopRadius;        // m

// Band bottoms (m above the ground sphere); the last band ends at the top (100 km).
constexpr std::array<double, 21> kBandEdges = {0.0,     500.0,   1000.0,  1500.0,  2000.0,  3000.0,  4000.0,
                                               5000.0,  6000.0,  8000.0,  10000.0, 12000.0, 15000.0, 20000.0,
                                               25000.0, 30000.0, 40000.0, 50000.0, 60000.0, 80000.0, 100000.0};
constexpr int kBands = static_cast<int>(kBandEdges.size()) - 1;

double tent(double a) { return std::max(0.0, 1.0 - std::abs(a - 25.0e3) / 15.0e3); }

struct Coefficients {  // one channel at one point, 1/m
  double rayleigh = 0.0, mie = 0.0, extinction = 0.0;
  double scattering() const { return rayleigh + mie; }
};

Coefficients coefficients(const McAtmosphere& a, int c, double alt) {
  Coefficients k;
  if (alt >= atmo::kThickness) return k;
  alt = std::max(alt, 0.0);
  const double dr = std::exp(-alt / a.rayleigh_scale_height), dm = std::exp(-alt / a.mie_scale_height);
  k.rayleigh = a.rayleigh_scattering[c] * dr;
  k.mie = a.mie_scattering * dm;
  k.extinction = k.rayleigh + a.mie_extinction * dm + a.ozone_absorption[c] * tent(alt);
  return k;
}

int band_of(double alt) {
  const auto it = std::upper_bound(kBandEdges.begin(), kBandEdges.end(), alt);
  return std::clamp(static_cast<int>(it - kBandEdges.begin()) - 1, 0, kBands - 1);
}

// Distances t > 0 at which the line p + t w crosses the sphere of radius R (0, 1 or 2).
// c = |p|^2 - R^2 as (r - R)(r + R) to keep the sign right within 1e-9 m of the sphere.
int sphere_roots(const glm::dvec3& p, const glm::dvec3& w, double R, double out[2]) {
  const double r = glm::length(p);
  const double b = glm::dot(p, w);
  const double c = (r - R) * (r + R);
  const double disc = b * b - c;
  if (disc < 0.0) return 0;
  const double s = std::sqrt(disc);
  // t0 = -b - s, t1 = -b + s, written without cancellation (t0 t1 = c)
  const double q = b > 0.0 ? -b - s : -b + s;
  double t0 = q, t1 = q != 0.0 ? c / q : 0.0;
  if (t0 > t1) std::swap(t0, t1);
  int n = 0;
  if (t0 > 0.0) out[n++] = t0;
  if (t1 > 0.0) out[n++] = t1;
  return n;
}

// A straight ray from p (inside the shell) along w, cut into segments of constant band
// majorant up to where it leaves the shell (ground or top); tentative collisions are drawn
// by advance() as a Poisson process of that piecewise-constant majorant.
class RayMajorant {
 public:
  RayMajorant(const glm::dvec3& p, const glm::dvec3& w, double scale, const std::array<double, kBands>& majorants) {
    double roots[2];
    // exit: the ground (if the line reaches it going forward) or the top
    exit_t_ = kInf;
    if (sphere_roots(p, w, kGround, roots) > 0 && glm::dot(p, w) < 0.0) {
      exit_t_ = roots[0];
      hits_ground_ = true;
    } else {
      const int n = sphere_roots(p, w, kTop, roots);
      exit_t_ = n > 0 ? roots[n - 1] : 0.0;
    }
    cuts_.clear();
    cuts_.push_back(0.0);
    for (int b = 1; b < kBands; ++b) {
      const int n = sphere_roots(p, w, kGround + kBandEdges[static_cast<std::size_t>(b)], roots);
      for (int i = 0; i < n; ++i)
        if (roots[i] < exit_t_) cuts_.push_back(roots[i]);
    }
    cuts_.push_back(exit_t_);
    std::sort(cuts_.begin(), cuts_.end());
    sigma_.resize(cuts_.size() - 1);
    for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
      const double tm = 0.5 * (cuts_[i] + cuts_[i + 1]);
      const double alt = glm::length(p + tm * w) - kGround;
      sigma_[i] = scale * majorants[static_cast<std::size_t>(band_of(alt))];
    }
  }

  // Moves to the next tentative collision, returning its distance (kInf once the ray has
  // left the shell) and the majorant there.
  double advance(double tau, double& sigma_maj) {
    while (seg_ < sigma_.size()) {
      const double t1 = cuts_[seg_ + 1];
      const double s = sigma_[seg_];
      if (s > 0.0) {
        const double need = tau / s;
        if (need < t1 - t_) {
          t_ += need;
          sigma_maj = s;
          return t_;
        }
        tau -= (t1 - t_) * s;
      }
      t_ = t1;
      ++seg_;
    }
    return kInf;
  }
  double exit_t() const { return exit_t_; }
  bool hits_ground() const { return hits_ground_; }

 private:
  std::vector<double> cuts_;
  std::vector<double> sigma_;
  std::size_t seg_ = 0;
  double t_ = 0.0;
  double exit_t_ = 0.0;
  bool hits_ground_ = false;
};

// Orthonormal basis completion (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
void basis(const glm::dvec3& n, glm::dvec3& b1, glm::dvec3& b2) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  b1 = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  b2 = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
}

glm::dvec3 around(const glm::dvec3& axis, double cos_theta, double phi) {
  glm::dvec3 b1, b2;
  basis(axis, b1, b2);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return glm::normalize(sin_theta * std::cos(phi) * b1 + sin_theta * std::sin(phi) * b2 + cos_theta * axis);
}

struct Tracer {
  const McAtmosphere& a;
  int c;
  glm::dvec3 sun;
  McSettings s;
  std::array<double, kBands> majorants{};
  model::Pcg32 rng;

  double u() { return rng.uniform(); }
  double exp_sample() { return -std::log1p(-u()); }

  // Ratio-tracking estimate of the transmittance from p towards the sun.
  double sun_transmittance(const glm::dvec3& p) {
    if (a.sun_irradiance == 0.0) return 0.0;
    RayMajorant ray(p, sun, 1.0, majorants);
    if (ray.hits_ground()) return 0.0;
    double T = 1.0, smaj = 0.0;
    for (;;) {
      const double t = ray.advance(exp_sample(), smaj);
      if (t == kInf) return T;
      const double alt = glm::length(p + t * sun) - kGround;
      T *= 1.0 - coefficients(a, c, alt).extinction / smaj;
    }
  }

  // In-scattered sun radiance per unit length and majorant at a tentative collision.
  double nee_medium(const glm::dvec3& x, const Coefficients& k, const glm::dvec3& w, double smaj) {
    if (a.sun_irradiance == 0.0) return 0.0;
    const double nu = glm::dot(w, sun);
    const double f = k.rayleigh * rayleigh_phase(nu) + k.mie * cornette_shanks_phase(nu, a.mie_g);
    if (f == 0.0) return 0.0;
    return a.sun_irradiance * f / smaj * sun_transmittance(x);
  }

  double nee_ground(const glm::dvec3& x) {
    const glm::dvec3 n = glm::normalize(x);
    const double mu = glm::dot(n, sun);
    if (mu <= 0.0 || a.sun_irradiance == 0.0) return 0.0;
    return a.sun_irradiance * a.ground_albedo[c] / kPi * mu * sun_transmittance(x);
  }

  glm::dvec3 sample_phase(const Coefficients& k, const glm::dvec3& w) {
    const double cos_t =
        u() * k.scattering() < k.rayleigh ? sample_rayleigh_cos(u()) : sample_cornette_shanks_cos(a.mie_g, rng);
    return around(w, cos_t, 2.0 * kPi * u());
  }

  glm::dvec3 on_ground(const glm::dvec3& x) { return glm::normalize(x) * (kGround + 1.0e-3); }

  // Radiance estimate along w from p (no unscattered sun: it is a delta direction) for a
  // path that has already scattered `order` times, times weight. Delta tracking.
  double diffuse(glm::dvec3 p, glm::dvec3 w, double weight, int order) {
    const double weight0 = weight;
    double sum = 0.0;
    while (weight > 0.0) {
      RayMajorant ray(p, w, 1.0, majorants);
      bool scattered = false;
      double smaj = 0.0;
      for (;;) {
        const double t = ray.advance(exp_sample(), smaj);
        if (t == kInf) break;
        const glm::dvec3 x = p + t * w;
        const Coefficients k = coefficients(a, c, glm::length(x) - kGround);
        if (order + 1 <= s.max_order) sum += weight * nee_medium(x, k, w, smaj);
        if (u() * smaj < k.extinction) {  // real collision
          if (k.extinction <= 0.0) break;
          weight *= k.scattering() / k.extinction;
          if (++order >= s.max_order) return sum;
          w = sample_phase(k, w);
          p = x;
          scattered = true;
          break;
        }
      }
      if (!scattered) {
        if (!ray.hits_ground()) return sum + weight * a.top_radiance;
        const glm::dvec3 x = on_ground(p + ray.exit_t() * w);
        if (order + 1 <= s.max_order) sum += weight * nee_ground(x);
        weight *= a.ground_albedo[c];
        if (++order >= s.max_order) return sum;
        const glm::dvec3 n = glm::normalize(x);
        w = around(n, std::sqrt(u()), 2.0 * kPi * u());  // cosine-weighted
        p = x;
      }
      if (weight < 0.05 * weight0) {  // Russian roulette
        const double q = weight / (0.05 * weight0);
        if (u() >= q) return sum;
        weight = 0.05 * weight0;
      }
    }
    return sum;
  }

  // One camera path: returns single and multiple contributions.
  void camera_path(const glm::dvec3& p0, const glm::dvec3& d, double& single, double& multiple) {
    single = multiple = 0.0;
    RayMajorant ray(p0, d, s.primary_majorant_scale, majorants);
    double w = 1.0, smaj = 0.0;
    for (;;) {
      const double t = ray.advance(exp_sample(), smaj);
      if (t == kInf) break;
      const glm::dvec3 x = p0 + t * d;
      const Coefficients k = coefficients(a, c, glm::length(x) - kGround);
      single += w * nee_medium(x, k, d, smaj);
      if (s.max_order >= 2 && k.scattering() > 0.0)
        multiple += diffuse(x, sample_phase(k, d), w * k.scattering() / smaj, 1);
      w *= 1.0 - k.extinction / smaj;
    }
    if (ray.hits_ground()) {
      const glm::dvec3 x = on_ground(p0 + ray.exit_t() * d);
      single += w * nee_ground(x);
      if (s.max_order >= 2)
        multiple += diffuse(x, around(glm::normalize(x), std::sqrt(u()), 2.0 * kPi * u()), w * a.ground_albedo[c], 1);
    } else {
      multiple += w * a.top_radiance;
    }
  }
};

struct Sums {
  double s = 0, s2 = 0, m = 0, m2 = 0, t = 0, t2 = 0;
};

McValue value(double sum, double sum2, long long n) {
  McValue v;
  v.mean = sum / static_cast<double>(n);
  const double var = std::max(0.0, (sum2 / static_cast<double>(n) - v.mean * v.mean)) * n / std::max(1.0, n - 1.0);
  v.std_error = std::sqrt(var / static_cast<double>(n));
  return v;
}

}  // namespace

double rayleigh_phase(double nu) { return 3.0 / (16.0 * kPi) * (1.0 + nu * nu); }

double cornette_shanks_phase(double nu, double g) {
  const double g2 = g * g;
  const double denom = 1.0 + g2 - 2.0 * g * nu;
  return 3.0 / (8.0 * kPi) * (1.0 - g2) / (2.0 + g2) * (1.0 + nu * nu) / (denom * std::sqrt(denom));
}

// CDF (3/8)(mu + 1 + (mu^3 + 1)/3) = u  <=>  mu^3 + 3 mu - (8u - 4) = 0, one real root
// (Cardano): mu = cbrt(z + sqrt(z^2 + 1)) + cbrt(z - sqrt(z^2 + 1)), z = 4u - 2.
double sample_rayleigh_cos(double u) {
  const double z = 4.0 * u - 2.0;
  const double s = std::sqrt(z * z + 1.0);
  return std::clamp(std::cbrt(z + s) + std::cbrt(z - s), -1.0, 1.0);
}

// Cornette-Shanks = HG(g) * 3 (1 + mu^2) / (2 (2 + g^2)) <= HG * 3 / (2 + g^2): sample HG by
// its inverse CDF, accept with probability (1 + mu^2) / 2.
double sample_cornette_shanks_cos(double g, model::Pcg32& rng) {
  for (;;) {
    const double u = rng.uniform();
    double mu;
    if (std::abs(g) < 1e-6) {
      mu = 2.0 * u - 1.0;
    } else {
      const double sq = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
      mu = std::clamp((1.0 + g * g - sq * sq) / (2.0 * g), -1.0, 1.0);
    }
    if (2.0 * rng.uniform() < 1.0 + mu * mu) return mu;
  }
}

int majorant_band_count() { return kBands; }
double majorant_band_bottom(int band) { return kBandEdges[static_cast<std::size_t>(band)]; }

double band_majorant(const McAtmosphere& a, int c, int band) {
  const double a0 = kBandEdges[static_cast<std::size_t>(band)], a1 = kBandEdges[static_cast<std::size_t>(band + 1)];
  const double tent_max = (a0 <= 25.0e3 && a1 >= 25.0e3) ? 1.0 : std::max(tent(a0), tent(a1));
  const double m = a.rayleigh_scattering[c] * std::exp(-a0 / a.rayleigh_scale_height) +
                   a.mie_extinction * std::exp(-a0 / a.mie_scale_height) + a.ozone_absorption[c] * tent_max;
  return m * (1.0 + 1e-9);
}

double extinction_at(const McAtmosphere& a, int c, double altitude_m) { return coefficients(a, c, altitude_m).extinction; }

double sun_transmittance_ratio_tracking(const McAtmosphere& a, int c, double altitude_m, double mu_s,
                                        model::Pcg32& rng) {
  const glm::dvec3 sun(std::sqrt(std::max(0.0, 1.0 - mu_s * mu_s)), 0.0, mu_s);
  McAtmosphere lit = a;
  lit.sun_irradiance = 1.0;
  Tracer tr{lit, c, sun, McSettings{}, {}, rng};
  for (int b = 0; b < kBands; ++b) tr.majorants[static_cast<std::size_t>(b)] = band_majorant(a, c, b);
  const double T = tr.sun_transmittance(glm::dvec3(0.0, 0.0, kGround + altitude_m));
  rng = tr.rng;  // hand the advanced state back
  return T;
}

McEstimate sky_radiance(const McAtmosphere& atmosphere, double camera_alt_m, const glm::dvec3& view,
                        const glm::dvec3& sun, int channel, const McSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const long long paths = std::max(0LL, settings.paths);
  const long long chunks = (paths + kPathsPerChunk - 1) / kPathsPerChunk;
  if (chunks > std::numeric_limits<int>::max()) throw std::invalid_argument("sky_radiance: too many paths");
  std::vector<Sums> sums(static_cast<std::size_t>(chunks));
  const glm::dvec3 p0(0.0, 0.0, atmo::radius_for_altitude(camera_alt_m));
  const glm::dvec3 d = glm::normalize(view), sn = glm::normalize(sun);
  // one seed per (settings.seed, channel), one stream per chunk of it
  const std::uint64_t seed = settings.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(channel);
  parallel_for(static_cast<int>(chunks), settings.threads, [&](int k) {
    Tracer tr{atmosphere, channel, sn, settings, {}, model::chunk_stream(seed, static_cast<std::uint64_t>(k))};
    for (int b = 0; b < kBands; ++b)
      tr.majorants[static_cast<std::size_t>(b)] = band_majorant(atmosphere, channel, b);
    Sums& S = sums[static_cast<std::size_t>(k)];
    const long long first = k * kPathsPerChunk, end = std::min(paths, first + kPathsPerChunk);
    for (long long i = first; i < end; ++i) {
      double single = 0.0, multiple = 0.0;
      tr.camera_path(p0, d, single, multiple);
      const double total = single + multiple;
      S.s += single;
      S.s2 += single * single;
      S.m += multiple;
      S.m2 += multiple * multiple;
      S.t += total;
      S.t2 += total * total;
    }
  });
  Sums all;  // in chunk order: the same sum on any number of threads
  for (const Sums& S : sums) {
    all.s += S.s, all.s2 += S.s2, all.m += S.m, all.m2 += S.m2, all.t += S.t, all.t2 += S.t2;
  }
  McEstimate e;
  e.paths = settings.paths;
  e.single = value(all.s, all.s2, settings.paths);
  e.multiple = value(all.m, all.m2, settings.paths);
  e.total = value(all.t, all.t2, settings.paths);
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

}  // namespace cloudsvc::reference::mc
