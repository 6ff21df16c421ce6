// Monte Carlo slab radiative transfer (renderer/model/slab_monte_carlo.h) and the
// renderer's light model for the same slab (renderer/model/slab_renderer_model.h):
// building blocks, physical limits with known answers, the Bouthors et al. 2008 transmittance band, and
// a printed error table of the renderer model against the Monte Carlo.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "renderer/model/droplet_optics.h"
#include "renderer/model/phase_function.h"
#include "renderer/model/slab_monte_carlo.h"
#include "renderer/model/slab_renderer_model.h"

namespace {

using namespace cloudsvc::model;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kDropletUm = 14.0;  // r_e = 7 um (Bouthors et al. 2008 §3.2)

// |a - b| within k combined standard errors plus an absolute slack.
void expect_within_se(double a, double se_a, double b, double se_b, double k, double slack, const char* what) {
  EXPECT_LE(std::fabs(a - b), k * std::hypot(se_a, se_b) + slack)
      << what << ": " << a << " ± " << se_a << " vs " << b << " ± " << se_b;
}

// Single-scattering radiance (L / F, sr^-1) of a homogeneous slab of optical depth tau
// lit by a collimated beam at mu0, leaving the top / bottom at |cos view| = mu with
// scattering-angle cosine cos_s (e.g. Liou 2002, "An Introduction to Atmospheric
// Radiation", §6.2 with P/4pi -> p):
//   top:    p mu0 / (mu0 + mu) (1 - e^{-tau (1/mu0 + 1/mu)})
//   bottom: p mu0 / (mu0 - mu) (e^{-tau/mu0} - e^{-tau/mu}),  -> p tau e^{-tau/mu0} / mu0 at mu = mu0
double single_scatter_radiance(double tau, double mu0, double mu, double p, bool top) {
  if (top) return p * mu0 / (mu0 + mu) * (1.0 - std::exp(-tau * (1.0 / mu0 + 1.0 / mu)));
  if (std::fabs(mu0 - mu) < 1e-9) return p * tau * std::exp(-tau / mu0) / mu0;
  return p * mu0 / (mu0 - mu) * (std::exp(-tau / mu0) - std::exp(-tau / mu));
}

double scattering_cosine(const ViewDirection& v, bool top, double sun_zenith_deg) {
  const glm::dvec3 s = sun_direction(sun_zenith_deg);
  return -glm::dot(s, view_travel_direction(v, top));  // incident direction is -s
}

// ---------------------------------------------------------------------------------
// Building blocks

TEST(SlabMcBuildingBlocks, Pcg32IsDeterministicAndUniform) {
  Pcg32 a(42, 7), b(42, 7), c(42, 8);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const std::uint32_t x = a.next_u32();
    EXPECT_EQ(x, b.next_u32());
    differs |= (x != c.next_u32());
  }
  EXPECT_TRUE(differs) << "different streams must give different sequences";
  // Mean and variance of U[0,1): 1/2 and 1/12, 1e6 samples (SE 2.9e-4 and 3e-4 rel.).
  double s = 0.0, s2 = 0.0;
  const int n = 1000000;
  for (int i = 0; i < n; ++i) {
    const double u = a.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    s += u;
    s2 += u * u;
  }
  EXPECT_NEAR(s / n, 0.5, 1.5e-3);
  EXPECT_NEAR(s2 / n - (s / n) * (s / n), 1.0 / 12.0, 1e-3);
}

// The JdD sampler against the phase function: probability of 1 - cos in log-spaced bins
// (the forward peak spans 1e-6 .. 1e-2) and the mean cosine (closed form).
TEST(SlabMcBuildingBlocks, PhaseSamplingMatchesJdD) {
  const JdDParams p = jdd_params(kDropletUm);
  Pcg32 rng(1, 1);
  constexpr int kBins = 16;
  std::array<double, kBins + 1> edges{};
  for (int i = 0; i <= kBins; ++i) edges[i] = i == 0 ? 0.0 : 2.0 * std::pow(1e-6, double(kBins - i) / kBins);
  std::array<int, kBins> count{};
  const int n = 1000000;
  double sum_mu = 0.0, sum_mu2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double mu = sample_jdd_cos_theta(p, rng);
    sum_mu += mu;
    sum_mu2 += mu * mu;
    const double u = 1.0 - mu;
    for (int b = 0; b < kBins; ++b)
      if (u >= edges[b] && u < edges[b + 1]) {
        ++count[b];
        break;
      }
  }
  for (int b = 0; b < kBins; ++b) {
    // Exact bin probability: 2 pi int p du (midpoint rule on 4000 sub-intervals).
    double prob = 0.0;
    const int m = 4000;
    const double h = (edges[b + 1] - edges[b]) / m;
    for (int k = 0; k < m; ++k) prob += jdd_phase(1.0 - (edges[b] + (k + 0.5) * h), p) * h;
    prob *= 2.0 * kPi;
    const double se = std::sqrt(prob * (1.0 - prob) / n);
    EXPECT_NEAR(count[b] / double(n), prob, 5.0 * se + 1e-4) << "bin " << b << " [" << edges[b] << ", " << edges[b + 1] << ")";
  }
  const double mean = sum_mu / n;
  const double se_mean = std::sqrt((sum_mu2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, jdd_mean_cosine(p), 4.0 * se_mean);
  // HG alone, including g < 0 and g = 0.
  for (double g : {-0.5, 0.0, 0.3, 0.95}) {
    double s = 0.0;
    for (int i = 0; i < 200000; ++i) s += sample_hg_cos_theta(g, rng.uniform());
    EXPECT_NEAR(s / 200000, g, 5e-3) << "g = " << g;
  }
}

// The new direction makes the requested angle with the old one, for vertical incident
// directions too (a sign error there once sent every first scatter at sun zenith 0
// downwards), and its azimuth is uniform: the mean of n over phi is cos_t · d.
TEST(SlabMcBuildingBlocks, ScatterDirectionKeepsTheAngle) {
  const glm::dvec3 dirs[] = {{0, 0, 1}, {0, 0, -1}, {0.6, 0.0, -0.8}, {0.0, std::sin(0.001), std::cos(0.001)}};
  for (const glm::dvec3& d : dirs) {
    for (double cos_t : {-0.9, -0.2, 0.0, 0.5, 0.999}) {
      glm::dvec3 mean(0.0);
      const int n = 64;
      for (int j = 0; j < n; ++j) {
        const glm::dvec3 v = scatter_direction(d, cos_t, 2.0 * kPi * (j + 0.5) / n);
        EXPECT_NEAR(glm::dot(v, v), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(v, d), cos_t, 1e-9) << "d = (" << d.x << ", " << d.y << ", " << d.z << ")";
        mean.x += v.x / n;
        mean.y += v.y / n;
        mean.z += v.z / n;
      }
      EXPECT_NEAR(mean.x, cos_t * d.x, 1e-9);
      EXPECT_NEAR(mean.y, cos_t * d.y, 1e-9);
      EXPECT_NEAR(mean.z, cos_t * d.z, 1e-9);
    }
  }
}

// ---------------------------------------------------------------------------------
// Monte Carlo: limits with known answers

// Every photon history leaves through the top or the bottom (albedo 1): R + T = 1,
// exactly per history with analog transport, in expectation with DDIS weights.
TEST(SlabMc, ConservesEnergy) {
  for (double tau : {1.0, 16.0}) {
    for (double sun : {0.0, 60.0}) {
      SCOPED_TRACE(testing::Message() << "tau " << tau << " sun " << sun);
      const SlabSpec slab = slab_from_optical_depth(tau, sun, kDropletUm);
      SlabMcOptions o;
      o.photons = 4000;
      o.views = {{0, 0}, {60, 0}};
      const SlabMcResult r = run_slab_monte_carlo(slab, o);
      EXPECT_EQ(r.lost_photons, 0u);
      EXPECT_NEAR(r.reflected_plus_transmitted.mean, 1.0, 3.0 * r.reflected_plus_transmitted.std_error + 1e-3);
      EXPECT_NEAR(r.transmitted.mean, r.transmitted_direct.mean + r.transmitted_diffuse.mean, 1e-12);
      o.ddis_probability = 0.0;
      const SlabMcResult a = run_slab_monte_carlo(slab, o);
      EXPECT_NEAR(a.reflected.mean + a.transmitted.mean, 1.0, 1e-12);
    }
  }
}

// tau -> 0: the unscattered beam is e^{-tau/mu0}; what scatters (1 - e^{-tau/mu0}) is
// split between R and T like single scattering: T_diffuse / (R + T_diffuse) -> the
// fraction of the phase function pointing below the horizon.
TEST(SlabMc, ThinSlabLimit) {
  const JdDParams p = jdd_params(kDropletUm);
  for (double sun : {0.0, 60.0}) {
    SCOPED_TRACE(testing::Message() << "sun " << sun);
    const double tau = 0.01, mu0 = std::cos(sun * kDeg);
    SlabMcOptions o;
    o.photons = 400000;
    const SlabMcResult r = run_slab_monte_carlo(slab_from_optical_depth(tau, sun, kDropletUm), o);
    const double direct = std::exp(-tau / mu0);
    EXPECT_NEAR(r.transmitted_direct.mean, direct, 4.0 * r.transmitted_direct.std_error);
    EXPECT_NEAR(r.transmitted.mean, r.transmitted_direct.mean + r.transmitted_diffuse.mean, 1e-12);
    const double scattered = r.reflected.mean + r.transmitted_diffuse.mean;
    EXPECT_GT(r.reflected.mean, 0.0);
    EXPECT_LT(r.transmitted_diffuse.mean, 1.0 - direct);
    // Downward fraction of single scattering: average over scattering azimuth of the
    // probability that the new direction points down (2-D quadrature in cos, phi).
    const glm::dvec3 in{-std::sin(sun * kDeg), 0.0, -mu0};
    double down = 0.0;
    const int nm = 20000, nphi = 64;
    for (int i = 0; i < nm; ++i) {
      // nodes uniform in ln(1 - mu) to resolve the forward peak
      const double a = std::log(1e-9), b = std::log(2.0);
      const double lu = a + (i + 0.5) * (b - a) / nm, u = std::exp(lu);
      const double w = 2.0 * kPi * jdd_phase(1.0 - u, p) * u * (b - a) / nm;
      int below = 0;
      for (int j = 0; j < nphi; ++j) below += scatter_direction(in, 1.0 - u, 2.0 * kPi * (j + 0.5) / nphi).z < 0.0;
      down += w * below / nphi;
    }
    const double frac = r.transmitted_diffuse.mean / scattered;
    // Second-order scattering (~tau/mu0 of the scattered light) shifts this by < 2 %.
    EXPECT_NEAR(frac, down, 0.02) << "MC " << frac << " single scattering " << down;
  }
}

// The first-collision part of the next-event radiance is single scattering, which has a
// closed form: this pins the estimator's normalisation (mu0, 1/mu, phase convention).
TEST(SlabMc, SingleScatteringRadianceMatchesClosedForm) {
  const JdDParams p = jdd_params(kDropletUm);
  const std::vector<ViewDirection> views = {{0, 0}, {60, 0}, {60, 180}, {30, 90}};
  for (double tau : {0.5, 2.0}) {
    for (double sun : {0.0, 60.0}) {
      SCOPED_TRACE(testing::Message() << "tau " << tau << " sun " << sun);
      SlabMcOptions o;
      o.photons = 40000;
      o.views = views;
      const SlabMcResult r = run_slab_monte_carlo(slab_from_optical_depth(tau, sun, kDropletUm), o);
      const double mu0 = std::cos(sun * kDeg);
      for (size_t k = 0; k < views.size(); ++k) {
        const double mu = std::cos(views[k].zenith_deg * kDeg);
        for (bool top : {true, false}) {
          const double exact =
              single_scatter_radiance(tau, mu0, mu, jdd_phase(scattering_cosine(views[k], top, sun), p), top);
          const Estimate& e = top ? r.radiance_top_single[k] : r.radiance_bottom_single[k];
          EXPECT_NEAR(e.mean, exact, 4.0 * e.std_error + 1e-3 * exact)
              << (top ? "top" : "bottom") << " view " << views[k].zenith_deg << "/" << views[k].rel_azimuth_deg;
          // All orders >= single scattering.
          const Estimate& all = top ? r.radiance_top[k] : r.radiance_bottom[k];
          EXPECT_GE(all.mean, e.mean);
        }
      }
    }
  }
}

// Two independent estimators of the reflected flux: counting photons that leave the top,
// and integrating the next-event radiance over the upper hemisphere,
//   R = (1 / mu0) int L mu dOmega  (L / F, mu0 F the incident flux),
// with 8-point Gauss-Legendre in mu and the midpoint rule in azimuth over [0, pi]
// (L is even in azimuth; at sun zenith 0 it does not depend on azimuth).
TEST(SlabMc, ReflectedRadianceIntegratesToReflectedFlux) {
  // Gauss-Legendre, 8 points on [-1, 1] (Abramowitz & Stegun Table 25.4).
  const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  std::vector<double> mu, wmu;
  for (int i = 0; i < 4; ++i)
    for (double s : {-1.0, 1.0}) {
      mu.push_back(0.5 * (1.0 + s * x[i]));
      wmu.push_back(0.5 * w[i]);
    }
  for (double sun : {0.0, 50.0}) {
    SCOPED_TRACE(testing::Message() << "sun " << sun);
    const int nphi = 6;
    SlabMcOptions o;
    o.photons = 30000;
    for (double m : mu)
      for (int j = 0; j < nphi; ++j) o.views.push_back({std::acos(m) / kDeg, 180.0 * (j + 0.5) / nphi});
    const SlabMcResult r = run_slab_monte_carlo(slab_from_optical_depth(4.0, sun, kDropletUm), o);
    double R = 0.0, var = 0.0;
    for (size_t i = 0; i < mu.size(); ++i)
      for (int j = 0; j < nphi; ++j) {
        const double f = mu[i] * wmu[i] * 2.0 * kPi / nphi / std::cos(sun * kDeg);
        R += r.radiance_top[i * nphi + j].mean * f;
        var += std::pow(r.radiance_top[i * nphi + j].std_error * f, 2);  // upper bound-ish: ignores correlation
      }
    std::printf("sun %2.0f: integrated R %.4f ± %.4f, counted R %.4f ± %.4f\n", sun, R, std::sqrt(var),
                r.reflected.mean, r.reflected.std_error);
    // Quadrature error < 1 %; the tolerance is ~3.5 standard errors of the difference.
    EXPECT_NEAR(R / r.reflected.mean, 1.0, 0.08);
  }
}

// Importance sampling must not change the answer: DDIS vs analog transport.
TEST(SlabMc, DetectorImportanceSamplingIsUnbiased) {
  const SlabSpec slab = slab_from_optical_depth(2.0, 60.0, kDropletUm);
  SlabMcOptions o;
  o.views = {{0, 0}, {60, 180}};
  o.photons = 40000;
  const SlabMcResult d = run_slab_monte_carlo(slab, o);
  o.ddis_probability = 0.0;
  o.photons = 200000;
  o.seed = 99;
  const SlabMcResult a = run_slab_monte_carlo(slab, o);
  expect_within_se(d.reflected.mean, d.reflected.std_error, a.reflected.mean, a.reflected.std_error, 4.0, 0.0, "R");
  for (size_t k = 0; k < o.views.size(); ++k) {
    expect_within_se(d.radiance_top[k].mean, d.radiance_top[k].std_error, a.radiance_top[k].mean,
                     a.radiance_top[k].std_error, 4.0, 0.0, "L top");
    expect_within_se(d.radiance_bottom[k].mean, d.radiance_bottom[k].std_error, a.radiance_bottom[k].mean,
                     a.radiance_bottom[k].std_error, 4.0, 0.0, "L bottom");
  }
}

// Results depend on the seed only, not on the number of threads: bit-identical for 1, 2
// and 5 threads and for all cores (threads = 0).
TEST(SlabMc, DeterministicForAnyThreadCount) {
  const SlabSpec slab = slab_from_optical_depth(4.0, 30.0, kDropletUm);
  SlabMcOptions o;
  o.photons = 3000;
  o.views = {{0, 0}};
  o.threads = 1;
  const SlabMcResult a = run_slab_monte_carlo(slab, o);
  for (int threads : {2, 5, 0}) {
    o.threads = threads;
    const SlabMcResult b = run_slab_monte_carlo(slab, o);
    EXPECT_EQ(a.reflected.mean, b.reflected.mean) << threads;
    EXPECT_EQ(a.reflected.std_error, b.reflected.std_error) << threads;
    EXPECT_EQ(a.transmitted.mean, b.transmitted.mean) << threads;
    EXPECT_EQ(a.radiance_top[0].mean, b.radiance_top[0].mean) << threads;
    EXPECT_EQ(a.radiance_bottom[0].mean, b.radiance_bottom[0].mean) << threads;
    EXPECT_EQ(a.radiance_bottom[0].std_error, b.radiance_bottom[0].std_error) << threads;
    EXPECT_EQ(a.mean_collisions, b.mean_collisions) << threads;
  }
  o.threads = 1;
  o.seed = 2;
  const SlabMcResult c = run_slab_monte_carlo(slab, o);
  EXPECT_NE(a.radiance_top[0].mean, c.radiance_top[0].mean);
}

// Diffuse transmittance against the two-stream formula for a conservative slab, normal
// incidence (Bohren 1987, the formula the shader uses): T = 1 / (1 + 3/4 (1 - g) tau).
// The MC must decrease with tau and stay within a loose factor: two-stream drops the
// boundary (extrapolation-length) terms, which make the exact T of a forward-peaked
// phase ~20-40 % larger at tau = 10-100.
TEST(SlabMc, DiffuseTransmittanceFollowsTwoStreamTrend) {
  const double g = jdd_mean_cosine(jdd_params(kDropletUm));
  double prev = 1.0;
  for (double tau : {10.0, 30.0, 100.0}) {
    SlabMcOptions o;
    o.photons = tau > 50.0 ? 3000 : 6000;
    const SlabMcResult r = run_slab_monte_carlo(slab_from_optical_depth(tau, 0.0, kDropletUm), o);
    const double two_stream = 1.0 / (1.0 + 0.75 * (1.0 - g) * tau);
    std::printf("tau %5.1f: MC T_diffuse %.4f ± %.4f, two-stream (g = %.4f) %.4f, ratio %.2f\n", tau,
                r.transmitted_diffuse.mean, r.transmitted_diffuse.std_error, g, two_stream,
                r.transmitted_diffuse.mean / two_stream);
    EXPECT_LT(r.transmitted_diffuse.mean, prev);
    EXPECT_GT(r.transmitted_diffuse.mean / two_stream, 1.0 / 1.5);
    EXPECT_LT(r.transmitted_diffuse.mean / two_stream, 2.0);
    prev = r.transmitted_diffuse.mean;
  }
}

// Bouthors et al. 2008, Appendices A and B (docs/SOURCES.md, "Slab multiple scattering"):
// a fit to the total transmittance of N0 = 300 cm^-3, r_e = 7 um clouds of thickness H. The paper's
// extinction uses Q_ext = 1 ("sigma = pi r_e^2", mean free path ~20 m), i.e. half the
// optical depth of the renderer's Q_ext = 2.
//  - In the paper's convention (Q_ext = 1) the MC reproduces the fit closely (within
//    ~4 % here): assert 12 %, which still allows another droplet phase function.
//  - With the renderer's Q_ext = 2 the slab is twice as thick optically, so T must be
//    lower, but not by more than the factor 2 that halving 1/(1 + k tau) can give at
//    most (observed 0.55-0.8): assert 0.45 < T / T_fit < 1.
TEST(SlabMc, BouthorsTransmittanceBand) {
  struct Row {
    double sun, H, fit;
  };
  const Row rows[] = {{0, 100, 0.8152}, {0, 500, 0.3988}, {0, 1000, 0.2400},
                      {60, 100, 0.5922}, {60, 500, 0.2700}, {60, 1000, 0.1625}};
  for (const Row& row : rows) {
    SCOPED_TRACE(testing::Message() << "sun " << row.sun << " H " << row.H);
    for (double q_ext : {1.0, 2.0}) {
      SlabSpec s;
      s.sigma_t_per_m = cloud_extinction_per_m(kDropletUm, kDefaultDropletNumberDensity_m3, q_ext);
      s.thickness_m = row.H;
      s.sun_zenith_deg = row.sun;
      s.droplet_diameter_um = kDropletUm;
      SlabMcOptions o;
      o.photons = s.optical_depth() > 50.0 ? 3000 : 6000;
      const SlabMcResult r = run_slab_monte_carlo(s, o);
      const double ratio = r.transmitted.mean / row.fit;
      std::printf("Bouthors 2008: sun %2.0f H %5.0f m Q_ext %.0f (tau %5.1f): MC T %.4f ± %.4f, fit %.4f, ratio %.3f\n",
                  row.sun, row.H, q_ext, s.optical_depth(), r.transmitted.mean, r.transmitted.std_error, row.fit, ratio);
      if (q_ext == 1.0) {
        EXPECT_NEAR(ratio, 1.0, 0.12);
      } else {
        EXPECT_GT(ratio, 0.45);
        EXPECT_LT(ratio, 1.0);
      }
    }
  }
}

// ---------------------------------------------------------------------------------
// Renderer model (a transcription of the cloud march: cloud_march.comp, cloud_lighting.glsl)

// With the sun term reduced to single scattering (the true phase, e^-tau), no diffuse term,
// no light-march cap and converged steps, the shader's march integrates the single-
// scattering radiance exactly: the transcription must reproduce the closed form.
TEST(SlabRendererModel, SingleScatteringWithoutDiffuseIsExact) {
  const JdDParams p = jdd_params(kDropletUm);
  SlabRendererModelOptions o = converged_renderer_model_options();
  o.peak_beam = false;
  o.diffuse = false;
  o.cap_light_march = false;
  o.cloud_t_eps = 0.0;
  for (double tau : {0.5, 4.0, 30.0}) {
    for (double sun : {0.0, 60.0, 80.0}) {
      for (const ViewDirection& v : {ViewDirection{0, 0}, ViewDirection{60, 0}, ViewDirection{45, 120}}) {
        const SlabSpec slab = slab_from_optical_depth(tau, sun, kDropletUm);
        const double mu0 = std::cos(sun * kDeg), mu = std::cos(v.zenith_deg * kDeg);
        for (bool top : {true, false}) {
          const double exact = single_scatter_radiance(tau, mu0, mu, jdd_phase(scattering_cosine(v, top, sun), p), top);
          const double model = slab_renderer_model_radiance(slab, v, top, o).radiance;
          EXPECT_NEAR(model, exact, 2e-3 * exact + 1e-12)
              << "tau " << tau << " sun " << sun << " view " << v.zenith_deg << "/" << v.rel_azimuth_deg
              << (top ? " top" : " bottom");
        }
      }
    }
  }
}

// Light march (light_optical_depth in shaders/cloud_lighting.glsl): optical depth to the
// top along the sun, capped at 4 km of path; and the diffuse in-scatter (diffuse_inscatter,
// same file) at the slab's faces.
TEST(SlabRendererModel, LightMarchAndDiffuseTermAsInTheShader) {
  const SlabSpec slab = slab_from_optical_depth(100.0, 80.0, kDropletUm);  // H = 1083 m
  SlabRendererModelOptions o;
  const double mu_s = std::cos(80.0 * kDeg);
  const double z = 100.0;
  const double full = slab.sigma_t_per_m * (slab.thickness_m - z) / mu_s;  // path 5670 m
  EXPECT_NEAR(slab_light_optical_depth(slab, z, o), slab.sigma_t_per_m * 4000.0, 1e-9);
  o.cap_light_march = false;
  EXPECT_NEAR(slab_light_optical_depth(slab, z, o), full, 1e-9 * full);
  // The sun's diffuse light: mu_s times the source table at the point's optical depths
  // above and below (14 um droplets: similarity scale 1), here light leaving the top
  // straight up and, 40 degrees from the vertical, towards and away from the sun.
  const double tau = slab.optical_depth();
  const glm::dvec3 up{0.0, 0.0, 1.0};
  const glm::dvec3 towards{std::sin(40.0 * kDeg), 0.0, std::cos(40.0 * kDeg)};
  const glm::dvec3 away{-towards.x, 0.0, towards.z};
  EXPECT_NEAR(slab_diffuse_inscatter(slab, slab.thickness_m, o, up), mu_s * ms_source_table().lookup(0.0, tau, mu_s, 1.0, 0.0),
              1e-12);
  EXPECT_NEAR(slab_diffuse_inscatter(slab, slab.thickness_m, o, away),
              mu_s * ms_source_table().lookup(0.0, tau, mu_s, towards.z, 180.0), 1e-12);
  // A low sun's light leaves the top of a thick cloud mostly forward, away from the sun.
  EXPECT_GT(slab_diffuse_inscatter(slab, slab.thickness_m, o, away), slab_diffuse_inscatter(slab, slab.thickness_m, o, towards));
  // Below the base, light travelling down carries more than light going up.
  EXPECT_GT(slab_diffuse_inscatter(slab, 0.0, o, -up), slab_diffuse_inscatter(slab, 0.0, o, up));
}

// ---------------------------------------------------------------------------------
// Error table: renderer model vs Monte Carlo, view zenith 0, reflected (camera above)
// and transmitted (camera below; the direct sun is excluded from both).
//
// Asserted band: what the light model (peak beam + Monte Carlo diffuse source table)
// meets with room for this test's own Monte Carlo noise (up to 20 % at tau 64); observed
// ratios model / MC 0.87-1.13 (2026-12-04; the earlier two-stream model: 0.73-1.84, the
// octave model before it 0.3-8). The table is printed so changes in either direction are
// visible.
TEST(SlabComparison, RendererModelVersusMonteCarloTable) {
  const ViewDirection nadir{0.0, 0.0};
  const SlabRendererModelOptions converged = converged_renderer_model_options();
  SlabRendererModelOptions shader64;
  shader64.jitter_samples = 8;
  std::printf("\n| tau | sun | side | MC ± se | model | model/MC | model 64 steps |\n");
  std::printf("|---:|---:|---|---:|---:|---:|---:|\n");
  for (double sun : {0.0, 60.0}) {
    for (double tau : {1.0, 4.0, 16.0, 64.0}) {
      const SlabSpec slab = slab_from_optical_depth(tau, sun, kDropletUm);
      SlabMcOptions o;
      o.photons = tau > 50.0 ? 12000 : tau > 10.0 ? 25000 : 60000;
      o.views = {nadir};
      const SlabMcResult r = run_slab_monte_carlo(slab, o);
      for (bool top : {true, false}) {
        const Estimate& e = top ? r.radiance_top[0] : r.radiance_bottom[0];
        const double m = slab_renderer_model_radiance(slab, nadir, top, converged).radiance;
        const double m64 = slab_renderer_model_radiance(slab, nadir, top, shader64).radiance;
        const double ratio = m / e.mean;
        std::printf("| %g | %g | %s | %.4g ± %.2g | %.4g | %.2f | %.4g |\n", tau, sun, top ? "R" : "T", e.mean,
                    e.std_error, m, ratio, m64);
        EXPECT_GT(e.mean, 0.0);
        EXPECT_LT(e.std_error, 0.2 * e.mean) << "MC too noisy for the bands below";
        SCOPED_TRACE(testing::Message() << "tau " << tau << " sun " << sun << (top ? " reflected" : " transmitted"));
        EXPECT_GT(ratio, 0.75);
        EXPECT_LT(ratio, 1.33);
      }
    }
  }
}

}  // namespace
