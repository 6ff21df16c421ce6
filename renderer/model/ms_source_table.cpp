// Diffuse multiple-scattering source of a cloud slab by Monte Carlo, and the peak beam
// (see ms_source_table.h).
#include "renderer/model/ms_source_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>

#include "common/parallel_for.h"
#include "renderer/model/slab_monte_carlo.h"

namespace cloudsvc::embedded {
extern const unsigned char ms_source_table[];  // renderer/model/data/ms_source_table.bin
extern const std::size_t ms_source_table_size;
extern const unsigned char ms_diffuse_incidence_table[];  // renderer/model/data/ms_diffuse_incidence_table.bin
extern const std::size_t ms_diffuse_incidence_table_size;
}  // namespace cloudsvc::embedded

namespace cloudsvc::model {

namespace {

constexpr double kPi = std::numbers::pi;

// A phase-like kernel of cos_theta tabulated at n uniform nodes over [-1, 1], linear in
// between: the collision estimator calls it 2 x (table directions) times per collision.
class TabulatedKernel {
 public:
  template <typename Fn>
  TabulatedKernel(int n, const Fn& fn) : values_(n) {
    for (int i = 0; i < n; ++i) values_[i] = fn(-1.0 + 2.0 * i / (n - 1));
  }
  double operator()(double mu) const {
    const double x = std::clamp((mu + 1.0) * 0.5, 0.0, 1.0) * static_cast<double>(values_.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), values_.size() - 2);
    const double t = x - static_cast<double>(i);
    return values_[i] + t * (values_[i + 1] - values_[i]);
  }

 private:
  std::vector<double> values_;
};

glm::dvec3 table_direction(const MsDirectionGrid& g, int k) {
  const int i_mu = k / g.n_phi, i_phi = k % g.n_phi;
  const double mu = -1.0 + 2.0 * i_mu / (g.n_mu - 1);
  const double phi = kPi * i_phi / (g.n_phi - 1);
  const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return {s * std::cos(phi), s * std::sin(phi), mu};
}

struct ChunkTally {
  std::vector<double> sum;  // [depth bin][direction]
  std::uint64_t lost = 0, collisions = 0;
};

}  // namespace

double ms_depth_coordinate(double tau_a, double tau_b) {
  tau_a = std::max(tau_a, 0.0);
  tau_b = std::max(tau_b, 0.0);
  const double h = 0.5 * (tau_a + tau_b);
  if (!(h > 1e-12)) return 0.5;
  const double den = 2.0 * std::log1p(h / kMsDepthScale);
  if (tau_a <= tau_b) return std::log1p(tau_a / kMsDepthScale) / den;
  return 1.0 - std::log1p(tau_b / kMsDepthScale) / den;
}

double ms_tau_above(double y, double tau) {
  const double h = 0.5 * tau;
  const double l = std::log1p(h / kMsDepthScale);
  if (y <= 0.5) return kMsDepthScale * std::expm1(2.0 * y * l);
  return tau - kMsDepthScale * std::expm1(2.0 * (1.0 - y) * l);
}

namespace {

// Node index and weight of coordinate c (in node units) on an axis of n nodes, clamped.
struct AxisWeight {
  int i0 = 0, i1 = 0;
  double t = 0.0;
};
AxisWeight axis_weight(double c, int n) {
  if (n < 2 || !(c > 0.0)) return {0, 0, 0.0};
  c = std::min(c, static_cast<double>(n - 1));
  const int i0 = std::min(static_cast<int>(c), n - 2);
  return {i0, i0 + 1, c - i0};
}

// Trilinear interpolation within one column block laid out [depth bin][mu_w][phi].
template <typename T>
double interpolate_column(const T* block, int depth_bins, const MsDirectionGrid& g, double y, double mu_w,
                          double phi_deg) {
  const AxisWeight ay = axis_weight(y * depth_bins - 0.5, depth_bins);
  const AxisWeight am = axis_weight((std::clamp(mu_w, -1.0, 1.0) + 1.0) * 0.5 * (g.n_mu - 1), g.n_mu);
  const double phi = std::fabs(std::remainder(phi_deg, 360.0));  // [0, 180]: the field is symmetric
  const AxisWeight ap = axis_weight(phi / 180.0 * (g.n_phi - 1), g.n_phi);
  const int nd = g.size();
  auto at = [&](int j, int m, int p) { return static_cast<double>(block[static_cast<std::size_t>(j) * nd + m * g.n_phi + p]); };
  auto plane = [&](int j) {
    const double a = at(j, am.i0, ap.i0) + ap.t * (at(j, am.i0, ap.i1) - at(j, am.i0, ap.i0));
    const double b = at(j, am.i1, ap.i0) + ap.t * (at(j, am.i1, ap.i1) - at(j, am.i1, ap.i0));
    return a + am.t * (b - a);
  };
  const double v0 = plane(ay.i0), v1 = plane(ay.i1);
  return v0 + ay.t * (v1 - v0);
}

}  // namespace

double MsSourceColumn::lookup(double y, double mu_w, double phi_deg) const {
  return interpolate_column(j_over_mu.data(), depth_bins, directions, y, mu_w, phi_deg);
}

MsSourceTable::MsSourceTable(const MsSourceTableShape& shape, std::vector<float> j_over_mu)
    : shape_(shape), values_(std::move(j_over_mu)) {
  if (shape.n_tau < 1 || shape.n_sun < 1 || shape.depth_bins < 2 || shape.directions.n_mu < 2 ||
      shape.directions.n_phi < 2 || values_.size() != shape.size())
    throw std::invalid_argument("ms source table: shape and value count disagree");
}

double MsSourceTable::lookup(double tau_a, double tau_b, double mu_s, double mu_w, double phi_deg) const {
  const double tau = std::max(tau_a, 0.0) + std::max(tau_b, 0.0);
  if (!(tau > 0.0) || values_.empty()) return 0.0;
  const double y = ms_depth_coordinate(tau_a, tau_b);
  const double thin_scale = std::min(tau / kMsTauMin, 1.0);  // J_d ~ tau in thin slabs
  const AxisWeight at = axis_weight(std::log2(std::max(tau, kMsTauMin) / kMsTauMin), shape_.n_tau);
  const double zenith_deg = std::acos(std::clamp(mu_s, 0.0, 1.0)) * 180.0 / kPi;
  const AxisWeight as = axis_weight(zenith_deg / kMsSunZenithMaxDeg * (shape_.n_sun - 1), shape_.n_sun);
  const std::size_t block = static_cast<std::size_t>(shape_.depth_bins) * shape_.directions.size();
  auto column = [&](int i, int j) {
    return interpolate_column(values_.data() + (static_cast<std::size_t>(i) * shape_.n_sun + j) * block,
                              shape_.depth_bins, shape_.directions, y, mu_w, phi_deg);
  };
  const double a = column(at.i0, as.i0) + as.t * (column(at.i0, as.i1) - column(at.i0, as.i0));
  const double b = column(at.i1, as.i0) + as.t * (column(at.i1, as.i1) - column(at.i1, as.i0));
  return thin_scale * std::max(a + at.t * (b - a), 0.0);
}

namespace {
constexpr unsigned char kMagic[4] = {'C', 'S', 'M', 'S'};
constexpr std::int32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 4 + 4 + 6 * 4;

void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<unsigned char>(v >> (8 * b)));
}
std::uint32_t get_u32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
}  // namespace

std::vector<unsigned char> MsSourceTable::serialise() const {
  std::vector<unsigned char> out(kMagic, kMagic + 4);
  put_u32(out, kVersion);
  for (int v : {shape_.n_tau, shape_.n_sun, shape_.depth_bins, shape_.directions.n_mu, shape_.directions.n_phi, 0})
    put_u32(out, static_cast<std::uint32_t>(v));
  for (float v : values_) {
    const std::uint16_t h = glm::packHalf1x16(v);
    out.push_back(static_cast<unsigned char>(h & 0xff));
    out.push_back(static_cast<unsigned char>(h >> 8));
  }
  return out;
}

MsSourceTable MsSourceTable::deserialise(const unsigned char* data, std::size_t size) {
  if (size < kHeaderBytes || !std::equal(kMagic, kMagic + 4, data) || get_u32(data + 4) != kVersion)
    throw std::runtime_error("ms source table: not a version-1 CSMS file");
  MsSourceTableShape shape;
  const unsigned char* h = data + 8;
  auto dim = [&](int k) {
    const std::uint32_t v = get_u32(h + 4 * k);
    if (v > 4096) throw std::runtime_error("ms source table: implausible dimension");
    return static_cast<int>(v);
  };
  shape.n_tau = dim(0);
  shape.n_sun = dim(1);
  shape.depth_bins = dim(2);
  shape.directions.n_mu = dim(3);
  shape.directions.n_phi = dim(4);
  if (size != kHeaderBytes + 2 * shape.size()) throw std::runtime_error("ms source table: size does not match its shape");
  std::vector<float> values(shape.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const unsigned char* p = data + kHeaderBytes + 2 * i;
    values[i] = glm::unpackHalf1x16(static_cast<std::uint16_t>(p[0] | p[1] << 8));
  }
  return MsSourceTable(shape, std::move(values));
}

const MsSourceTable& ms_diffuse_incidence_table() {
  static const MsSourceTable table =
      MsSourceTable::deserialise(embedded::ms_diffuse_incidence_table, embedded::ms_diffuse_incidence_table_size);
  return table;
}

const MsSourceTable& ms_source_table() {
  static const MsSourceTable table = MsSourceTable::deserialise(embedded::ms_source_table, embedded::ms_source_table_size);
  return table;
}

MsSourceTableBuild build_ms_source_table(MsSourceTableShape shape, const JdDParams& phase,
                                         double photons_scale, std::uint64_t seed, int threads,
                                         bool diffuse_incidence) {
  if (diffuse_incidence) shape.n_sun = 1;  // no sun: one column per optical depth
  MsSourceTableBuild out;
  std::vector<float> values;
  values.reserve(shape.size());
  for (int i = 0; i < shape.n_tau; ++i) {
    for (int j = 0; j < shape.n_sun; ++j) {
      const double tau = kMsTauMin * std::exp2(i);
      const double zenith = shape.n_sun > 1 ? kMsSunZenithMaxDeg * j / (shape.n_sun - 1) : 0.0;
      MsSourceOptions o;
      o.photons = static_cast<std::uint64_t>(photons_scale * 4.0e6 / std::pow(1.0 + tau, 0.75)) + 4000;
      o.seed = seed + static_cast<std::uint64_t>(i * shape.n_sun + j);
      o.threads = threads;
      o.depth_bins = shape.depth_bins;
      o.directions = shape.directions;
      o.diffuse_incidence = diffuse_incidence;
      MsSourceColumn c = compute_ms_source_column(tau, std::cos(zenith * kPi / 180.0), phase, o);
      for (double v : c.j_over_mu) values.push_back(static_cast<float>(v));
      out.columns.push_back(std::move(c));
    }
  }
  out.table = MsSourceTable(shape, std::move(values));
  return out;
}

MsSourceColumn compute_ms_source_column(double tau, double mu_s, const JdDParams& phase,
                                        const MsSourceOptions& options) {
  if (options.diffuse_incidence) mu_s = 1.0;  // no sun: any valid value passes the check below
  if (!(tau > 0.0) || !(mu_s > 0.0 && mu_s <= 1.0) || options.depth_bins < 2 || options.chunks < 2 ||
      options.directions.n_mu < 2 || options.directions.n_phi < 2)
    throw std::invalid_argument("ms source column: needs tau > 0, 0 < mu_s <= 1, >= 2 bins, chunks and directions");
  const auto t_start = std::chrono::steady_clock::now();
  const double f = 1.0 - phase.w_d;  // weight of the diffraction peak
  const TabulatedKernel kernel(16385, [&](double mu) {
    const double kernel_g = options.diffuse_incidence ? kMsDiffuseIncidenceKernelG : kMsKernelG;
    return f * hg_phase(mu, kernel_g) + (1.0 - f) * draine_phase(mu, phase.g_d, phase.alpha);
  });
  const MsDirectionGrid grid = options.directions;
  const int nd = grid.size(), nb = options.depth_bins;
  std::vector<glm::dvec3> dirs(nd);
  for (int k = 0; k < nd; ++k) dirs[k] = table_direction(grid, k);
  const glm::dvec3 sun_travel{-std::sqrt(std::max(0.0, 1.0 - mu_s * mu_s)), 0.0, -mu_s};

  const int chunks = options.chunks;
  std::vector<ChunkTally> tallies(chunks);
  const std::uint64_t per_chunk = options.photons / chunks, extra = options.photons % chunks;
  parallel_for(chunks, options.threads, [&](int chunk) {
    ChunkTally& out = tallies[chunk];
    out.sum.assign(static_cast<std::size_t>(nb) * nd, 0.0);
    Pcg32 rng = chunk_stream(options.seed, static_cast<std::uint64_t>(chunk));
    const std::uint64_t n = per_chunk + (static_cast<std::uint64_t>(chunk) < extra ? 1 : 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      // Optical-depth coordinates: z from the base (0) to the top (tau), extinction 1.
      double z = tau;
      glm::dvec3 d = sun_travel;
      bool diffuse = false;  // scattered at least once through the Draine lobe
      if (options.diffuse_incidence) {  // cosine-weighted downward: mu = sqrt(u)
        const double mu = std::sqrt(rng.uniform()), phi = 2.0 * kPi * rng.uniform();
        const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        d = {s * std::cos(phi), s * std::sin(phi), -mu};
        diffuse = true;
      }
      std::uint64_t collisions = 0;
      for (;;) {
        const double zn = z - std::log(1.0 - rng.uniform()) * d.z;
        if (!(zn > 0.0 && zn < tau)) break;  // escapes through the base or the top
        z = zn;
        if (++collisions > options.max_collisions) {
          ++out.lost;
          break;
        }
        if (diffuse) {
          const double y = ms_depth_coordinate(tau - z, z);
          const int bin = std::clamp(static_cast<int>(y * nb), 0, nb - 1);
          double* row = out.sum.data() + static_cast<std::size_t>(bin) * nd;
          const glm::dvec3 m{d.x, -d.y, d.z};  // the azimuthal mirror image: the field is symmetric
          for (int k = 0; k < nd; ++k) row[k] += 0.5 * (kernel(glm::dot(d, dirs[k])) + kernel(glm::dot(m, dirs[k])));
        }
        double cos_t;
        if (rng.uniform() < phase.w_d) {
          cos_t = sample_draine_cos_theta(phase.g_d, phase.alpha, rng);
          diffuse = true;
        } else {
          cos_t = sample_hg_cos_theta(phase.g_hg, rng.uniform());
        }
        d = scatter_direction(d, cos_t, 2.0 * kPi * rng.uniform());
      }
      out.collisions += collisions;
    }
  });

  // Diffuse incidence has no preferred azimuth: every azimuth node estimates the same
  // source, so each chunk's tally is folded to the mean over the nodes of its zenith
  // cosine (less Monte Carlo noise; the standard errors below are of the folded means).
  if (options.diffuse_incidence) {
    for (ChunkTally& t : tallies)
      for (int j = 0; j < nb; ++j)
        for (int i_mu = 0; i_mu < grid.n_mu; ++i_mu) {
          double* row = t.sum.data() + static_cast<std::size_t>(j) * nd + static_cast<std::size_t>(i_mu) * grid.n_phi;
          double mean = 0.0;
          for (int i = 0; i < grid.n_phi; ++i) mean += row[i];
          mean /= grid.n_phi;
          for (int i = 0; i < grid.n_phi; ++i) row[i] = mean;
        }
  }

  MsSourceColumn col;
  col.tau = tau;
  col.mu_s = mu_s;
  col.depth_bins = nb;
  col.directions = grid;
  col.j_over_mu.assign(static_cast<std::size_t>(nb) * nd, 0.0);
  col.std_error.assign(col.j_over_mu.size(), 0.0);
  col.photons = options.photons;
  std::uint64_t collisions = 0;
  for (const ChunkTally& t : tallies) {
    col.lost_photons += t.lost;
    collisions += t.collisions;
  }
  col.mean_collisions = static_cast<double>(collisions) / static_cast<double>(std::max<std::uint64_t>(1, options.photons));
  // Per unit horizontal flux a photon stands for 1 / N; the collision density per unit
  // optical depth of the bin gives the source: J_d / mu_s = sum / (N dtau_bin).
  for (int j = 0; j < nb; ++j) {
    const double dtau = ms_tau_above((j + 1.0) / nb, tau) - ms_tau_above(static_cast<double>(j) / nb, tau);
    for (int k = 0; k < nd; ++k) {
      const std::size_t idx = static_cast<std::size_t>(j) * nd + k;
      double s = 0.0, s2 = 0.0;
      for (int c = 0; c < chunks; ++c) {
        // chunk mean, normalised as if the whole run were this chunk
        const double nc = static_cast<double>(per_chunk + (static_cast<std::uint64_t>(c) < extra ? 1 : 0));
        const double m = tallies[c].sum[idx] / (nc * dtau);
        s += tallies[c].sum[idx];
        s2 += m * m;
      }
      const double mean = s / (static_cast<double>(options.photons) * dtau);
      col.j_over_mu[idx] = mean;
      const double var = std::max(0.0, (s2 - chunks * mean * mean) / (chunks - 1.0));
      col.std_error[idx] = std::sqrt(var / chunks);
    }
  }
  col.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return col;
}

double peak_beam_phase(double cos_theta, double tau, const JdDParams& phase) {
  tau = std::max(tau, 0.0);
  const double f = 1.0 - phase.w_d;
  const double beam = std::exp(-phase.w_d * tau);  // sum over k of e^-tau (f tau)^k / k!
  double sum = phase.w_d * draine_phase(cos_theta, phase.g_d, phase.alpha) * beam;
  double term = std::exp(-tau), mass = 0.0, g = phase.g_hg;
  for (int k = 0; k < kPeakBeamOrders && mass < kPeakBeamMassDone * beam; ++k) {
    sum += f * term * hg_phase(cos_theta, g);
    mass += term;
    term *= f * tau / (k + 1.0);
    g *= phase.g_hg;
  }
  return sum + f * std::max(beam - mass, 0.0) * hg_phase(cos_theta, g);
}

double peak_beam_slowest_decay() { return jdd_params(5.0).w_d; }  // the fit's smallest diameter

double peak_beam_cutoff_tau(double cos_theta, const JdDParams& phase, double negligible) {
  double lobe = 0.0, g = phase.g_hg;
  for (int k = 0; k <= kPeakBeamOrders; ++k, g *= phase.g_hg) lobe = std::max(lobe, hg_phase(cos_theta, g));
  const double bound = (1.0 - phase.w_d) * lobe + phase.w_d * draine_phase(cos_theta, phase.g_d, phase.alpha);
  return std::log(std::max(bound / negligible, 1.0)) / phase.w_d;
}

double ms_similarity_scale(const JdDParams& phase) {
  static const double table_g = jdd_mean_cosine(jdd_params(kMsTableDropletUm));
  return (1.0 - jdd_mean_cosine(phase)) / (1.0 - table_g);
}

}  // namespace cloudsvc::model
