// Lorenz-Mie series for a homogeneous sphere and its size-distribution average (see
// mie.h for conventions and sources).
#include "renderer/model/mie.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>

#include "common/parallel_for.h"

namespace cloudsvc::model {

namespace {

using cplx = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// Absorption with Im m >= 0 whatever convention the caller used (see mie.h).
cplx bh_index(cplx m) { return {m.real(), std::abs(m.imag())}; }

}  // namespace

int mie_n_stop(double x) {
  return std::max(1, static_cast<int>(std::lround(x + 4.0 * std::cbrt(x) + 2.0)));
}

// Lentz 1976 / Press et al. "modified Lentz" evaluation of
//   J_{nu-1}(z) / J_nu(z) = b0 - 1/(b1 - 1/(b2 - ...)),  b_j = 2 (nu + j) / z,
// nu = n + 1/2, which follows from J_{nu-1} + J_{nu+1} = (2 nu / z) J_nu. Then
//   D_n = psi_n'/psi_n = 1/(2z) + J_nu'/J_nu = -n/z + J_{nu-1}/J_nu.
// The fraction converges for any z once nu + j exceeds |z| by a few |z|^(1/3).
cplx mie_log_derivative_cf(cplx z, int n) {
  if (n < 0) throw std::invalid_argument("mie_log_derivative_cf: n < 0");
  constexpr double kTiny = 1e-300;
  constexpr double kTol = 1e-15;
  const cplx inv_z = 1.0 / z;
  const double nu = n + 0.5;
  cplx f = 2.0 * nu * inv_z;
  if (std::abs(f) == 0.0) f = kTiny;
  cplx c = f;
  cplx d = 0.0;
  const long max_iter = 1000000 + 4 * static_cast<long>(std::abs(z));
  for (long j = 1; j < max_iter; ++j) {
    const cplx bj = 2.0 * (nu + static_cast<double>(j)) * inv_z;
    d = bj - d;  // b_j + a_j d_{j-1}, a_j = -1
    if (std::abs(d) == 0.0) d = kTiny;
    d = 1.0 / d;
    c = bj - 1.0 / c;  // b_j + a_j / c_{j-1}
    if (std::abs(c) == 0.0) c = kTiny;
    const cplx delta = c * d;
    f *= delta;
    if (std::abs(delta - 1.0) < kTol) break;
  }
  return -static_cast<double>(n) * inv_z + f;
}

std::vector<cplx> mie_log_derivatives(cplx z, int n_max) {
  if (n_max < 0) throw std::invalid_argument("mie_log_derivatives: n_max < 0");
  // Start 40 above both n_max and |z| (the brief's "+40 or more"); the start value is
  // the continued fraction, so the margin only keeps that fraction short.
  const int n_start =
      std::max(n_max, static_cast<int>(std::ceil(std::abs(z)))) + 40;
  std::vector<cplx> out(static_cast<std::size_t>(n_max) + 1);
  cplx d = mie_log_derivative_cf(z, n_start);
  for (int n = n_start; n >= 1; --n) {
    const cplx n_over_z = static_cast<double>(n) / z;
    d = n_over_z - 1.0 / (d + n_over_z);  // now D_{n-1}
    if (n - 1 <= n_max) out[static_cast<std::size_t>(n - 1)] = d;
  }
  return out;
}

// B&H eq. 4.88 with the logarithmic derivative (their BHMIE form):
//   a_n = [(D_n/m + n/x) psi_n - psi_{n-1}] / [(D_n/m + n/x) xi_n - xi_{n-1}]
//   b_n = [(m D_n + n/x) psi_n - psi_{n-1}] / [(m D_n + n/x) xi_n - xi_{n-1}]
// psi_n(x) = x j_n(x), chi_n(x) = -x y_n(x), xi_n = psi_n - i chi_n; both satisfy
// f_n = ((2n - 1)/x) f_{n-1} - f_{n-2} with psi_{-1} = cos x, psi_0 = sin x,
// chi_{-1} = -sin x, chi_0 = cos x. chi_n grows (stable upward); psi_n decays past
// n ~ x, but only by ~1e-4 at n_stop, so the upward error stays ~1e-12 (Wiscombe 1980).
MieCoefficients mie_coefficients(cplx m_in, double x) {
  if (!(x > 0.0)) throw std::invalid_argument("mie_coefficients: x must be > 0");
  const cplx m = bh_index(m_in);
  if (!(m.real() > 0.0)) throw std::invalid_argument("mie_coefficients: Re m must be > 0");
  const int n_stop = mie_n_stop(x);
  const std::vector<cplx> dn = mie_log_derivatives(m * x, n_stop);

  MieCoefficients c;
  c.x = x;
  c.m = m;
  c.a.resize(static_cast<std::size_t>(n_stop));
  c.b.resize(static_cast<std::size_t>(n_stop));
  double psi_prev = std::cos(x), psi = std::sin(x);  // psi_{n-2}, psi_{n-1} at n = 1
  double chi_prev = -std::sin(x), chi = std::cos(x);
  for (int n = 1; n <= n_stop; ++n) {
    const double k = (2.0 * n - 1.0) / x;
    const double psi_n = k * psi - psi_prev;
    const double chi_n = k * chi - chi_prev;
    const cplx xi_n(psi_n, -chi_n), xi_nm1(psi, -chi);
    const double n_over_x = n / x;
    const cplx da = dn[static_cast<std::size_t>(n)] / m + n_over_x;
    const cplx db = dn[static_cast<std::size_t>(n)] * m + n_over_x;
    c.a[static_cast<std::size_t>(n - 1)] = (da * psi_n - psi) / (da * xi_n - xi_nm1);
    c.b[static_cast<std::size_t>(n - 1)] = (db * psi_n - psi) / (db * xi_n - xi_nm1);
    psi_prev = psi;
    psi = psi_n;
    chi_prev = chi;
    chi = chi_n;
  }
  return c;
}

// B&H 4.61, 4.62, 4.74 (g Q_sca), 4.82 (Q_back).
MieEfficiencies mie_efficiencies(const MieCoefficients& c) {
  const std::size_t terms = c.a.size();
  double s_ext = 0.0, s_sca = 0.0, s_g = 0.0;
  cplx s_back = 0.0;
  for (std::size_t i = 0; i < terms; ++i) {
    const double n = static_cast<double>(i + 1);
    const cplx an = c.a[i], bn = c.b[i];
    s_ext += (2.0 * n + 1.0) * (an.real() + bn.real());
    s_sca += (2.0 * n + 1.0) * (std::norm(an) + std::norm(bn));
    s_g += (2.0 * n + 1.0) / (n * (n + 1.0)) * (an * std::conj(bn)).real();
    if (i + 1 < terms) {
      const cplx an1 = c.a[i + 1], bn1 = c.b[i + 1];
      s_g += n * (n + 2.0) / (n + 1.0) *
             (an * std::conj(an1) + bn * std::conj(bn1)).real();
    }
    s_back += (2.0 * n + 1.0) * ((i % 2 == 0) ? -1.0 : 1.0) * (an - bn);  // (-1)^n
  }
  const double x2 = c.x * c.x;
  MieEfficiencies e;
  e.q_ext = 2.0 / x2 * s_ext;
  e.q_sca = 2.0 / x2 * s_sca;
  e.g = e.q_sca > 0.0 ? 4.0 / x2 * s_g / e.q_sca : 0.0;
  e.q_back = std::norm(s_back) / x2;
  return e;
}

// S1 = sum (2n+1)/(n(n+1)) (a_n pi_n + b_n tau_n), S2 = sum ... (a_n tau_n + b_n pi_n),
//   pi_0 = 0, pi_1 = 1, pi_{n+1} = ((2n+1)/n) mu pi_n - ((n+1)/n) pi_{n-1},
//   tau_n = n mu pi_n - (n+1) pi_{n-1}                                  (B&H 4.47, 4.74).
MieAmplitudes mie_amplitudes(const MieCoefficients& c, double mu) {
  cplx s1 = 0.0, s2 = 0.0;
  double pi_prev = 0.0, pi_n = 1.0;
  const std::size_t terms = c.a.size();
  for (std::size_t i = 0; i < terms; ++i) {
    const double n = static_cast<double>(i + 1);
    const double tau_n = n * mu * pi_n - (n + 1.0) * pi_prev;
    const double f = (2.0 * n + 1.0) / (n * (n + 1.0));
    s1 += f * (c.a[i] * pi_n + c.b[i] * tau_n);
    s2 += f * (c.a[i] * tau_n + c.b[i] * pi_n);
    const double pi_next = ((2.0 * n + 1.0) * mu * pi_n - (n + 1.0) * pi_prev) / n;
    pi_prev = pi_n;
    pi_n = pi_next;
  }
  return {s1, s2};
}

namespace {

// The angles of a list grouped in mirror pairs: a base cosine mu >= 0 with the indices of
// the list's +mu and -mu (-1 when absent). Since pi_n(-mu) = (-1)^(n-1) pi_n(mu) and
// tau_n(-mu) = (-1)^n tau_n(mu) (B&H 4.47), one recurrence in n serves both angles of a
// pair once the sums over odd and even n are kept apart.
struct MirrorAngles {
  std::vector<double> mu;
  std::vector<std::ptrdiff_t> plus, minus;
};

MirrorAngles mirror_angles(const std::vector<double>& cos_theta) {
  // cos(pi - t) and -cos(t) differ by an ulp or two; a base cosine this close to the other
  // angle's changes the phase by ~ n^2 kSameCosine ~ 1e-9 relative.
  constexpr double kSameCosine = 1e-14;
  std::vector<std::size_t> order(cos_theta.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return std::abs(cos_theta[a]) < std::abs(cos_theta[b]); });
  MirrorAngles m;
  for (std::size_t k = 0; k < order.size();) {
    const double base = std::abs(cos_theta[order[k]]);
    std::ptrdiff_t plus = -1, minus = -1;
    for (; k < order.size() && std::abs(cos_theta[order[k]]) - base <= kSameCosine; ++k) {
      const std::ptrdiff_t i = static_cast<std::ptrdiff_t>(order[k]);
      if (!std::signbit(cos_theta[order[k]]) && plus < 0) {
        plus = i;
      } else if (std::signbit(cos_theta[order[k]]) && minus < 0) {
        minus = i;
      } else {
        break;
      }
    }
    m.mu.push_back(plus >= 0 ? cos_theta[static_cast<std::size_t>(plus)] : -cos_theta[static_cast<std::size_t>(minus)]);
    m.plus.push_back(plus);
    m.minus.push_back(minus);
  }
  return m;
}

// mie_phase on angles already paired by mirror_angles; out has one value per angle of the
// list they came from (angle_count).
//
// dC_sca/dOmega = (|S1|^2 + |S2|^2) / (2 k^2) and C_sca = Q_sca pi r^2, so with x = k r
//   p = (|S1|^2 + |S2|^2) / (2 pi x^2 Q_sca).
// The sums of mie_amplitudes for a pair of base angles at a time, the series index inside,
// and each base angle's mirror image (theta, 180 deg - theta) from the same recurrence: per
// parity of n the four partial sums P = f a pi, T = f b tau, Q = f a tau, R = f b pi, then
//   S1(mu)  = P + T over all n,   S1(-mu) = (P - T)_odd - (P - T)_even,
//   S2(mu)  = Q + R over all n,   S2(-mu) = (R - Q)_odd + (Q - R)_even.
std::vector<double> mie_phase_mirrored(const MieCoefficients& c, double q_sca, const MirrorAngles& m,
                                       std::size_t angle_count) {
  const std::size_t nb = m.mu.size();
  // The series' factors per term n = i + 1: f a_n, f b_n (f = (2n+1)/(n(n+1))) and the
  // recurrence's n, n + 1, (2n+1)/n, (n+1)/n.
  const std::size_t terms = c.a.size();
  std::vector<double> ar(terms), ai(terms), br(terms), bi(terms), nn(terms), n1(terms), k1(terms), k2(terms);
  for (std::size_t i = 0; i < terms; ++i) {
    const double n = static_cast<double>(i + 1);
    const double f = (2.0 * n + 1.0) / (n * (n + 1.0));
    ar[i] = f * c.a[i].real();
    ai[i] = f * c.a[i].imag();
    br[i] = f * c.b[i].real();
    bi[i] = f * c.b[i].imag();
    nn[i] = n;
    n1[i] = n + 1.0;
    k1[i] = (2.0 * n + 1.0) / n;
    k2[i] = (n + 1.0) / n;
  }
  std::vector<double> out(angle_count);
  const double norm = 1.0 / (2.0 * kPi * c.x * c.x * q_sca);
  // Two base angles in one SIMD register (GCC/Clang vector extension) with the sums in
  // registers: the series over all angles at once, streaming the sums through memory once
  // per term, was memory-bound (and, bounds-checked under AddressSanitizer, ~100x slower).
  constexpr std::size_t kLanes = 2;
  using Pair = double __attribute__((vector_size(8 * kLanes)));
  struct Sums {  // per parity of n: P, T, Q, R (see above), real and imaginary parts
    Pair p_re{}, p_im{}, t_re{}, t_im{}, q_re{}, q_im{}, r_re{}, r_im{};
  };
  for (std::size_t j0 = 0; j0 < nb; j0 += kLanes) {
    Pair mu, pp, pn;
    for (std::size_t l = 0; l < kLanes; ++l) {
      mu[l] = j0 + l < nb ? m.mu[j0 + l] : 0.0;
      pp[l] = 0.0;
      pn[l] = 1.0;
    }
    Sums odd, even;
    const auto term = [&, a_r = ar.data(), a_i = ai.data(), b_r = br.data(), b_i = bi.data(), n = nn.data(),
                       n_1 = n1.data(), c1 = k1.data(), c2 = k2.data()](std::size_t i, Sums& s) __attribute__((always_inline)) {
      const Pair tau_n = n[i] * mu * pn - n_1[i] * pp;
      s.p_re += a_r[i] * pn;
      s.p_im += a_i[i] * pn;
      s.t_re += b_r[i] * tau_n;
      s.t_im += b_i[i] * tau_n;
      s.q_re += a_r[i] * tau_n;
      s.q_im += a_i[i] * tau_n;
      s.r_re += b_r[i] * pn;
      s.r_im += b_i[i] * pn;
      const Pair next = c1[i] * mu * pn - c2[i] * pp;
      pp = pn;
      pn = next;
    };
    std::size_t i = 0;
    for (; i + 1 < terms; i += 2) {  // i = n - 1: i even for odd n
      term(i, odd);
      term(i + 1, even);
    }
    if (i < terms) term(i, odd);
    for (std::size_t l = 0; l < kLanes && j0 + l < nb; ++l) {
      const std::size_t j = j0 + l;
      if (m.plus[j] >= 0) {
        const double s1r = odd.p_re[l] + odd.t_re[l] + even.p_re[l] + even.t_re[l];
        const double s1i = odd.p_im[l] + odd.t_im[l] + even.p_im[l] + even.t_im[l];
        const double s2r = odd.q_re[l] + odd.r_re[l] + even.q_re[l] + even.r_re[l];
        const double s2i = odd.q_im[l] + odd.r_im[l] + even.q_im[l] + even.r_im[l];
        out[static_cast<std::size_t>(m.plus[j])] = (s1r * s1r + s1i * s1i + s2r * s2r + s2i * s2i) * norm;
      }
      if (m.minus[j] >= 0) {
        const double s1r = (odd.p_re[l] - odd.t_re[l]) - (even.p_re[l] - even.t_re[l]);
        const double s1i = (odd.p_im[l] - odd.t_im[l]) - (even.p_im[l] - even.t_im[l]);
        const double s2r = (odd.r_re[l] - odd.q_re[l]) + (even.q_re[l] - even.r_re[l]);
        const double s2i = (odd.r_im[l] - odd.q_im[l]) + (even.q_im[l] - even.r_im[l]);
        out[static_cast<std::size_t>(m.minus[j])] = (s1r * s1r + s1i * s1i + s2r * s2r + s2i * s2i) * norm;
      }
    }
  }
  return out;
}

MieSingle mie_single_mirrored(cplx m, double x, const MirrorAngles& mirrored, std::size_t angle_count) {
  const MieCoefficients c = mie_coefficients(m, x);
  MieSingle out;
  out.eff = mie_efficiencies(c);
  out.phase = mie_phase_mirrored(c, out.eff.q_sca, mirrored, angle_count);
  return out;
}

}  // namespace

std::vector<double> mie_phase(const MieCoefficients& c, double q_sca, const std::vector<double>& cos_theta) {
  return mie_phase_mirrored(c, q_sca, mirror_angles(cos_theta), cos_theta.size());
}

MieSingle mie_single(cplx m, double x, const std::vector<double>& cos_theta) {
  return mie_single_mirrored(m, x, mirror_angles(cos_theta), cos_theta.size());
}

// ---- size distribution -----------------------------------------------------------

namespace {

// Diameter range [lo, hi] (um) outside which n(d) is < ~1e-8 of its peak.
void diameter_range(const DropletSpectrum& s, double& lo, double& hi) {
  const double d = s.mean_diameter_um, sp = s.relative_spread;
  if (s.shape == DropletShape::kGamma) {
    lo = std::max(d * (1.0 - 6.0 * sp), 1e-3 * d);
    hi = d * (1.0 + 8.0 * sp);  // right-skewed (skewness 2 sp)
  } else {
    const double sigma = std::sqrt(std::log1p(sp * sp));
    const double mu = std::log(d) - 0.5 * sigma * sigma;
    lo = std::exp(mu - 7.0 * sigma);
    hi = std::exp(mu + 7.0 * sigma);
  }
}

// ln n(d) up to a constant (the constants cancel in the weighted averages).
double log_number_density(const DropletSpectrum& s, double d) {
  const double sp = s.relative_spread;
  if (s.shape == DropletShape::kGamma) {
    const double k = 1.0 / (sp * sp);
    return (k - 1.0) * std::log(d / s.mean_diameter_um) - k * (d / s.mean_diameter_um - 1.0);
  }
  const double sigma2 = std::log1p(sp * sp);
  const double mu = std::log(s.mean_diameter_um) - 0.5 * sigma2;
  const double t = std::log(d) - mu;
  return -t * t / (2.0 * sigma2) - std::log(d);
}

}  // namespace

MieAverage mie_size_average(const DropletSpectrum& s, const std::vector<double>& cos_theta, int threads) {
  if (!(s.mean_diameter_um > 0.0) || !(s.wavelength_um > 0.0) || !(s.relative_spread >= 0.0) ||
      !(s.size_parameter_step > 0.0))
    throw std::invalid_argument("mie_size_average: bad spectrum");
  const double x_per_um = kPi / s.wavelength_um;  // x = pi d / lambda

  std::vector<double> diam, weight;
  if (s.relative_spread == 0.0) {
    diam = {s.mean_diameter_um};
    weight = {1.0};
  } else {
    double lo = 0.0, hi = 0.0;
    diameter_range(s, lo, hi);
    int n = s.sizes;
    if (n <= 0) n = std::max(64, static_cast<int>(std::ceil((hi - lo) * x_per_um / s.size_parameter_step)) + 1);
    n = std::max(n, 3);
    const double h = (hi - lo) / (n - 1);
    for (int i = 0; i < n; ++i) {
      const double d = lo + h * i;
      const double end = (i == 0 || i == n - 1) ? 0.5 : 1.0;  // trapezoid
      diam.push_back(d);
      weight.push_back(end * std::exp(log_number_density(s, d)));
    }
  }

  // Partial sums per chunk of kChunk sizes (d^2, d^3, d^2 Q_ext, d^2 Q_sca, d^2 Q_sca g,
  // then the phase), added up in chunk order below.
  constexpr int kChunk = 16;
  const int sizes = static_cast<int>(diam.size());
  const int chunks = (sizes + kChunk - 1) / kChunk;
  const std::size_t nj = cos_theta.size();
  const MirrorAngles mirrored = mirror_angles(cos_theta);  // the same angles for every size
  std::vector<std::vector<double>> partial(static_cast<std::size_t>(chunks));
  parallel_for(chunks, threads, [&](int k) {
    std::vector<double>& acc = partial[static_cast<std::size_t>(k)];
    acc.assign(5 + nj, 0.0);
    for (int i = k * kChunk; i < std::min(sizes, (k + 1) * kChunk); ++i) {
      const double d = diam[static_cast<std::size_t>(i)], w = weight[static_cast<std::size_t>(i)];
      if (w == 0.0) continue;
      const MieSingle one = mie_single_mirrored(s.m, x_per_um * d, mirrored, nj);
      const double d2 = d * d;
      const double c_sca = w * d2 * one.eff.q_sca;  // proportional to n(d) C_sca(d) dd
      acc[0] += w * d2;
      acc[1] += w * d2 * d;
      acc[2] += w * d2 * one.eff.q_ext;
      acc[3] += c_sca;
      acc[4] += c_sca * one.eff.g;
      for (std::size_t j = 0; j < nj; ++j) acc[5 + j] += c_sca * one.phase[j];
    }
  });
  std::vector<double> total(5 + nj, 0.0);
  for (const std::vector<double>& acc : partial)
    for (std::size_t j = 0; j < total.size(); ++j) total[j] += acc[j];

  MieAverage out;
  out.sizes = sizes;
  out.q_ext = total[2] / total[0];
  out.q_sca = total[3] / total[0];
  out.g = total[4] / total[3];
  out.effective_diameter_um = total[1] / total[0];
  out.phase.assign(total.begin() + 5, total.end());
  for (double& p : out.phase) p /= total[3];
  return out;
}

}  // namespace cloudsvc::model
