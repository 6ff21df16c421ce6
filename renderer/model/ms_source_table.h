// Multiple scattering in a cloud slab split at the droplets' diffraction peak, for a light
// model that adds an exactly marched sun term to a tabulated diffuse source.
//
// The droplet phase function of Jendersie & d'Eon 2023 is a blend
//   p = f HG(g_HG) + (1 - f) D(g_D, alpha),   f = 1 - w_D ~ 0.5,  g_HG ~ 0.99,
// whose HG lobe is the diffraction peak (a few degrees wide) and whose Draine lobe is
// the rest. Light that has scattered only through the peak still travels along the sun's
// beam; light that has scattered at least once through the Draine lobe is diffuse. So:
//
// * The peak beam (peak_beam_phase): after k peak scatterings along a slant optical
//   depth tau the beam keeps the Poisson fraction e^-tau (f tau)^k / k! and is spread by
//   the k-fold convolution of HG(g_HG), which is HG(g_HG^k) exactly (HG's Legendre
//   moments are g^l). Scattered once more towards the camera it gives, per unit sun
//   irradiance and unit scattering,
//     sum_k e^-tau (f tau)^k / k! [f HG(mu; g_HG^(k+1)) + (1 - f) D(mu)]
//   (the Draine lobe is ~25 degrees wide, so its blur by HG(g_HG^k) is neglected); k = 0
//   is single scattering. The Draine part sums to (1 - f) D(mu) e^-(1 - f) tau, the
//   delta-scaled beam of Joseph, Wiscombe & Weinman 1976.
// * The diffuse source J_d(z, w): radiance scattered into direction w at depth z by light
//   that has scattered at least once through the Draine lobe, J_d = int p(w . w') I_d(w')
//   dw'. It is smooth in w (no diffraction peak: that lobe only re-emits I_d nearly
//   unchanged), so a coarse table of it from Monte Carlo serves any view. The same split
//   (exact single scattering plus a smooth multiple-scattering field from the truncated
//   phase function) is Nakajima & Tanaka's 1988 TMS correction (JQSRT 40, 51).
//
// compute_ms_source_column runs the Monte Carlo for one slab and sun: a conservative
// homogeneous slab of optical depth tau under a sun of zenith cosine mu_s, black ground.
// The estimator is the collision estimator of J_d: every collision of a diffuse photon
// arriving along d adds p(d . w) for each table direction w, divided by the depth bin's
// optical thickness and the photon count. To keep its variance finite, the HG peak in that
// p is replaced by HG(kMsKernelG) (a ~10 degree smoothing of I_d, which varies over tens
// of degrees).
//
// Units: optical depths (dimensionless); J_d in sr^-1 per unit solar irradiance measured
// normal to the beam, stored divided by mu_s (per unit horizontal solar flux).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/model/phase_function.h"

namespace cloudsvc::model {

// Depth coordinate y in [0, 1] of a point with optical depths tau_a above and tau_b below
// it in a slab: log-spaced from each boundary towards the middle (y = 1/2), so the
// fast variation within a few optical depths of the top and the base gets most nodes:
//   y = ln(1 + tau_a / t0) / (2 ln(1 + h / t0))        for tau_a <= tau_b, h = (tau_a + tau_b) / 2,
//   y = 1 - ln(1 + tau_b / t0) / (2 ln(1 + h / t0))    otherwise,  t0 = kMsDepthScale.
// In thin slabs (h << t0) this tends to tau_a / (tau_a + tau_b).
inline constexpr double kMsDepthScale = 0.5;
double ms_depth_coordinate(double tau_a, double tau_b);
// Inverse: optical depth below the top at coordinate y in a slab of optical depth tau.
double ms_tau_above(double y, double tau);

// The asymmetry of the HG kernel that stands in for the diffraction peak in the
// collision estimator (see above).
inline constexpr double kMsKernelG = 0.95;
// ... in the table of diffuse incidence (MsSourceOptions::diffuse_incidence): narrower
// (~4 degrees), because the incident light stops at the horizon and a wider kernel spreads
// it into upward directions. Reflected flux of a slab of optical depth 0.5 under diffuse
// light, from the table against the slab flux table's Monte Carlo: +13 % with 0.95,
// +7 % with 0.98 (MsDiffuseIncidenceTable.ReflectsAndTransmitsTheSlabFluxes); the price is
// about twice the noise for the same photons.
inline constexpr double kMsDiffuseIncidenceKernelG = 0.98;

// Table directions: the travel direction w of the scattered light, by its zenith cosine
// (-1 down .. 1 up) and its azimuth relative to the sun's (0: travelling towards the
// sun's side, 180: away from it; the field is symmetric in the sign of the azimuth).
struct MsDirectionGrid {
  int n_mu = 9;    // mu_k = -1 + 2 k / (n_mu - 1)
  int n_phi = 5;   // phi_k = 180 deg k / (n_phi - 1)
  int size() const { return n_mu * n_phi; }
};

struct MsSourceOptions {
  std::uint64_t photons = 20000;
  std::uint64_t seed = 1;
  int threads = 0;                       // 0: all cores (common/parallel_for.h)
  int chunks = 64;                       // fixed work units, each with its own PCG32 stream
  int depth_bins = 24;                   // uniform in ms_depth_coordinate
  MsDirectionGrid directions;
  std::uint64_t max_collisions = 100000000;  // per photon; beyond it the photon is lost
  // Diffuse (Lambertian) light entering through the top instead of the sun's beam: photons
  // start cosine-weighted over the downward hemisphere and every collision counts (there is
  // no marched beam to leave out); the column is then J per unit incident horizontal flux
  // and mu_s is ignored. The field has no preferred azimuth, so the tally is averaged over
  // the azimuth nodes (every node holds the same value). By symmetry the same column,
  // turned upside down, is the source of diffuse light entering through the base (the
  // ground's).
  bool diffuse_incidence = false;
};

// J_d / mu_s for one slab and sun, at the centre y_j = (j + 1/2) / depth_bins of each depth
// bin (bin-averaged) and each table direction: value(j, k) = j_over_mu[j * n_dir + k],
// with k = i_mu * n_phi + i_phi. std_error from the spread of the chunk means.
struct MsSourceColumn {
  double tau = 0.0, mu_s = 1.0;
  int depth_bins = 0;
  MsDirectionGrid directions;
  std::vector<double> j_over_mu, std_error;
  std::uint64_t photons = 0, lost_photons = 0;
  double mean_collisions = 0.0;
  double seconds = 0.0;

  // Linear interpolation in y (clamped to the first and last bin centres) and bilinear in
  // the direction (mu_w: zenith cosine of w; phi_deg: relative azimuth, any sign).
  double lookup(double y, double mu_w, double phi_deg) const;
};

MsSourceColumn compute_ms_source_column(double tau, double mu_s, const JdDParams& phase,
                                        const MsSourceOptions& options);

// The diffuse source of every slab and sun the renderer meets: one Monte Carlo column per
// node of a grid in total optical depth and sun zenith angle, interpolated linearly in
// log2 tau, the sun's zenith angle, y and the direction (what the shader does with its
// 3-D texture, shaders/cloud_lighting.glsl). Generated by build/bin/ms_source_table and
// stored in renderer/model/data/ms_source_table.bin (embedded at build time).
//
// Grid: tau_i = kMsTauMin 2^i (i < n_tau), sun zenith theta_j = kMsSunZenithMaxDeg j /
// (n_sun - 1), depth bins and directions as in MsSourceColumn. Outside it: thinner slabs
// scale the source linearly with tau (few collisions: J_d ~ tau), thicker ones and lower
// suns clamp to the last node (the source, J_d / mu_s times mu_s, still goes to 0 at the
// horizon).
inline constexpr double kMsTauMin = 0.25;
inline constexpr double kMsSunZenithMaxDeg = 84.0;

struct MsSourceTableShape {
  int n_tau = 12, n_sun = 8, depth_bins = 16;
  MsDirectionGrid directions;
  std::size_t size() const {
    return static_cast<std::size_t>(n_tau) * n_sun * depth_bins * directions.size();
  }
};

class MsSourceTable {
 public:
  MsSourceTable() = default;
  MsSourceTable(const MsSourceTableShape& shape, std::vector<float> j_over_mu);

  const MsSourceTableShape& shape() const { return shape_; }
  // Values in storage order [tau][sun][depth bin][mu_w][phi] (phi fastest).
  const std::vector<float>& values() const { return values_; }
  bool empty() const { return values_.empty(); }

  // J_d / mu_s (sr^-1 per unit horizontal solar flux) at a point with optical depths
  // tau_a above and tau_b below it, sun zenith cosine mu_s, scattered light travelling
  // with zenith cosine mu_w at relative azimuth phi_deg (see MsDirectionGrid).
  double lookup(double tau_a, double tau_b, double mu_s, double mu_w, double phi_deg) const;

  // Serialised form (the data file): magic "CSMS", version 1, the shape as six int32
  // (n_tau, n_sun, depth_bins, n_mu, n_phi, 0), then the values as IEEE binary16,
  // all little-endian.
  std::vector<unsigned char> serialise() const;
  static MsSourceTable deserialise(const unsigned char* data, std::size_t size);

 private:
  MsSourceTableShape shape_;
  std::vector<float> values_;
};

// The table the renderer uses (the embedded data file), parsed once.
const MsSourceTable& ms_source_table();

// Monte Carlo of every column of the grid (build/bin/ms_source_table). photons_scale
// sets MsSourceOptions::photons per column to photons_scale * 4e6 / (1 + tau)^0.75 + 4000
// (collisions per photon grow ~ linearly with tau; the transmitted part, which thick
// slabs make rare, needs the extra photons).
struct MsSourceTableBuild {
  MsSourceTable table;
  std::vector<MsSourceColumn> columns;  // [tau][sun], with their standard errors
};
// diffuse_incidence: the table of diffuse light entering through the top
// (MsSourceOptions::diffuse_incidence), one column per optical depth (shape.n_sun is 1).
MsSourceTableBuild build_ms_source_table(MsSourceTableShape shape, const JdDParams& phase,
                                         double photons_scale, std::uint64_t seed, int threads,
                                         bool diffuse_incidence = false);

// The source of diffuse (Lambertian) light entering a slab through its top, per unit
// incident horizontal flux (sr^-1): lookup(tau_a, tau_b, any mu_s, mu_w, any phi). Light
// entering through the base: lookup(tau_b, tau_a, ., -mu_w, .). Generated by
// build/bin/ms_source_table --diffuse into renderer/model/data/ms_diffuse_incidence_table.bin.
const MsSourceTable& ms_diffuse_incidence_table();

// The peak beam's in-scatter (see above) per unit sun irradiance and unit scattering,
// sr^-1: cos_theta between the sun's travel direction and the scattered light's, tau the
// slant optical depth from the point to where the sun's beam enters the cloud. Sums at most
// kPeakBeamOrders peak orders, until they hold kPeakBeamMassDone of the beam; the rest of
// the Poisson mass takes the next order's lobe (shaders/phase_function.glsl, the same).
inline constexpr int kPeakBeamOrders = 8;
inline constexpr double kPeakBeamMassDone = 0.999;
double peak_beam_phase(double cos_theta, double tau, const JdDParams& phase);
// The peak beam decays as e^(-w_D tau); w_D grows with the droplet size, so over the fit's
// droplets (5-50 um) this smallest w_D is the slowest decay a light march has to follow.
double peak_beam_slowest_decay();
// The optical depth towards the sun beyond which the peak beam scattered by cos_theta stays
// below `negligible` (sr^-1 per unit sun irradiance) for any optical depth: the peak beam
// is at most [f max_k HG(cos; g_HG^(k+1)) + w_D D(cos)] e^(-w_D tau), k = 0 ..
// kPeakBeamOrders (the Poisson weights sum to e^(-w_D tau)), so a light march may stop
// there (RenderQuality::light_march_cutoff, shaders/phase_function.glsl, the same). 0
// where the bound is below `negligible` even unshadowed. The march uses kPeakBeamNegligible
// times the sun's zenith cosine at the camera (at least 0.05): ~0.1 % of the diffuse light
// of a sunlit cloud, whose source is 0.02-0.3 sr^-1 per unit horizontal solar flux.
inline constexpr double kPeakBeamNegligible = 1e-4;
double peak_beam_cutoff_tau(double cos_theta, const JdDParams& phase, double negligible);

// The droplet size the table is computed for (Bouthors et al. 2008's r_e = 7 um) and the
// similarity scale that maps another phase function onto it: optical depths times
// (1 - g) / (1 - g_table), g the mean cosine (van de Hulst's similarity relation: diffuse
// light depends on (1 - g) tau).
inline constexpr double kMsTableDropletUm = 14.0;
double ms_similarity_scale(const JdDParams& phase);

}  // namespace cloudsvc::model
