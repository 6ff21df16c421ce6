// Ray / spherical-shell intersection (geodesy/shell_intersection.h) against an
// independent long-double evaluation in explicit 3D coordinates, in double and in
// float, plus the naive float quadratic on Earth-centred coordinates as a contrast
// (docs/SOURCES.md, "Ray / shell intersection in float": 26.4 m and 7.6 m off where the
// altitude form is ~1 mm off).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "geodesy/shell_intersection.h"

namespace {

using cloudsvc::geo::intersect_shell;
using cloudsvc::geo::ShellHits;

constexpr double kPi = 3.14159265358979323846;
constexpr double kR = 6360000.0;  // ground radius used by the atmosphere (Hillaire 2020), m

// ---------------------------------------------------------------------------------
// Reference: origin O = (0, 0, R + h), direction D = (sin t, 0, cos t) with cos t = mu,
// solve |O + s D|^2 = (R + H)^2 in long double (64-bit mantissa on x86-64) with the
// stable quadratic (q = -(B + sign(B) sqrt(B^2 - C)), roots q and C / q), building the
// coefficients from the 3D vectors rather than from the altitude form under test.
struct RefHits {
  int count = 0;
  long double t_near = 0, t_far = 0;
  // |dt/dmu| bound, (R + h)(1 + |B| / sqrt(disc)): the conditioning of the roots, which
  // grows without bound at the tangent (disc -> 0).
  long double dt_dmu = 0;
};
RefHits reference(long double R, long double h, long double H, long double mu) {
  const long double st = std::sqrt(std::max(0.0L, 1.0L - mu * mu));
  const long double o[3] = {0.0L, 0.0L, R + h};
  const long double d[3] = {st, 0.0L, mu};
  const long double rs = R + H;
  const long double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const long double od = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const long double oo = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
  const long double A = dd, B = od, C = oo - rs * rs;  // A s^2 + 2 B s + C = 0
  const long double disc = B * B - A * C;
  RefHits r;
  if (disc < 0) return r;
  const long double sq = std::sqrt(disc);
  r.dt_dmu = (R + h) * (1.0L + std::fabs(B) / std::max(sq, 1e-30L));
  const long double q = -(B + (B >= 0 ? sq : -sq));
  long double t0 = (q != 0) ? C / q : 0.0L, t1 = q / A;
  if (t0 > t1) std::swap(t0, t1);
  if (t1 < 0) return r;
  if (t0 < 0) {
    r.count = 1;
    r.t_near = t1;
    return r;
  }
  r.count = 2;
  r.t_near = t0;
  r.t_far = t1;
  return r;
}

// Naive float: the textbook a t^2 + b t + c = 0 on Earth-centred float coordinates,
// nearest non-negative root. This is what the altitude form replaces.
float naive_float_near(float R, float h, float H, float mu) {
  const float st = std::sqrt(1.0f - mu * mu);
  const float ox = 0.0f, oy = 0.0f, oz = R + h;
  const float dx = st, dy = 0.0f, dz = mu;
  const float a = dx * dx + dy * dy + dz * dz;
  const float b = 2.0f * (ox * dx + oy * dy + oz * dz);
  const float rs = R + H;
  const float c = (ox * ox + oy * oy + oz * oz) - rs * rs;
  const float disc = b * b - 4.0f * a * c;
  const float s = std::sqrt(std::max(disc, 0.0f));
  const float t0 = (-b - s) / (2.0f * a), t1 = (-b + s) / (2.0f * a);
  return t0 >= 0.0f ? t0 : t1;
}

double mu_from_depression_deg(double deg) { return -std::sin(deg * kPi / 180.0); }

// |O|sin(t) = R + H at the tangent: mu_t = -sqrt(1 - ((R + H) / (R + h))^2), h > H.
double tangent_mu(double R, double h, double H) {
  const double k = (R + H) / (R + h);
  return -std::sqrt((1.0 - k) * (1.0 + k));
}

// ---------------------------------------------------------------------------------
// Double precision: every camera/shell/direction combination against the reference.

TEST(ShellIntersection, DoubleMatchesLongDoubleReference) {
  const double cams[] = {0.0, 2.0, 1499.0, 1500.0, 1501.0, 2000.0, 10000.0, 100000.0};
  const double shells[] = {1500.0, 10000.0};
  std::vector<double> mus = {-1.0, -0.5, -0.1, -0.0157, -1e-3, -1e-5, 0.0,
                             1e-5, 1e-3, 0.0157, 0.1, 0.5, 1.0};
  double worst_abs = 0.0, worst_ratio = 0.0, worst_away = 0.0;
  int compared = 0;
  for (double R : {kR, 6371000.0}) {
    for (double h : cams) {
      for (double H : shells) {
        std::vector<double> all = mus;
        if (h > H) {  // grazing directions around the tangent
          const double mt = tangent_mu(R, h, H);
          for (double eps : {-1e-3, -1e-5, -1e-7, -1e-9, 1e-9, 1e-7, 1e-5, 1e-3})
            all.push_back(mt + eps * std::fabs(mt));
        }
        for (double mu : all) {
          SCOPED_TRACE(testing::Message() << "R " << R << " h " << h << " H " << H
                                          << " mu " << mu);
          const ShellHits<double> got = intersect_shell(R, h, H, mu);
          const RefHits ref = reference(R, h, H, mu);
          ASSERT_EQ(got.count, ref.count);
          auto check = [&](double t, long double tr) {
            const double err = std::fabs(double(t - tr));
            // 1e-6 m, or 1e-12 relative on long rays (t up to 1.3e7 m through the Earth),
            // plus what 4 ulps of mu move the root: the form is backward stable, and next
            // to the tangent dt/dmu diverges, so no method can do better there.
            const double ulp_mu = 4.0 * 2.2e-16 * std::fabs(mu);
            const double tol = 1e-6 + 1e-12 * double(tr) + ulp_mu * double(ref.dt_dmu);
            EXPECT_LE(err, tol);
            worst_abs = std::max(worst_abs, err);
            worst_ratio = std::max(worst_ratio, err / tol);
            if (ulp_mu * double(ref.dt_dmu) < 1e-6) worst_away = std::max(worst_away, err);
            ++compared;
          };
          if (ref.count >= 1) check(got.t_near, ref.t_near);
          if (ref.count == 2) check(got.t_far, ref.t_far);
        }
      }
    }
  }
  std::printf("double vs long double: %d distances, worst %.3g m (%.3g m where the problem "
              "is well conditioned), worst error/tolerance %.3g\n",
              compared, worst_abs, worst_away, worst_ratio);
}

// Counts by position relative to the shell.
TEST(ShellIntersection, InsideOutsideAndOnTheShell) {
  const double R = kR, H = 1500.0;
  // Below the shell: always exactly one hit ahead, whatever the direction.
  for (double mu : {-1.0, -0.3, 0.0, 0.3, 1.0}) {
    const ShellHits<double> s = intersect_shell(R, 100.0, H, mu);
    EXPECT_EQ(s.count, 1) << mu;
    EXPECT_GT(s.t_near, 0.0);
  }
  EXPECT_NEAR(intersect_shell(R, 100.0, H, 1.0).t_near, 1400.0, 1e-9);   // straight up
  EXPECT_NEAR(intersect_shell(R, 100.0, H, -1.0).t_near,                 // straight down,
              2.0 * R + 100.0 + H, 1e-6);                                // through the Earth
  // Above: none looking up or level, two looking down.
  EXPECT_EQ(intersect_shell(R, 2000.0, H, 0.5).count, 0);
  EXPECT_EQ(intersect_shell(R, 2000.0, H, 0.0).count, 0);
  const ShellHits<double> down = intersect_shell(R, 2000.0, H, -1.0);
  EXPECT_EQ(down.count, 2);
  EXPECT_NEAR(down.t_near, 500.0, 1e-9);
  EXPECT_NEAR(down.t_far, 500.0 + 2.0 * (R + H), 1e-6);
  // Exactly on the shell (h == H): a root at t = 0.
  const ShellHits<double> on_down = intersect_shell(R, H, H, -0.2);
  EXPECT_EQ(on_down.count, 2);
  EXPECT_EQ(on_down.t_near, 0.0);
  EXPECT_NEAR(on_down.t_far, 2.0 * (R + H) * 0.2, 1e-6);
  const ShellHits<double> on_up = intersect_shell(R, H, H, 0.2);
  EXPECT_EQ(on_up.count, 1);
  EXPECT_EQ(on_up.t_near, 0.0);
  const ShellHits<double> on_level = intersect_shell(R, H, H, 0.0);
  EXPECT_EQ(on_level.count, 2);
  EXPECT_EQ(on_level.t_near, 0.0);
  EXPECT_EQ(on_level.t_far, 0.0);
  // Same in float.
  EXPECT_EQ(intersect_shell<float>(float(R), float(H), float(H), -0.2f).count, 2);
  EXPECT_EQ(intersect_shell<float>(float(R), float(H), float(H), 0.2f).count, 1);
}

TEST(ShellIntersection, TangentRay) {
  const double R = kR, h = 10000.0, H = 1500.0;
  const double mt = tangent_mu(R, h, H);
  const double t_tangent = std::sqrt((R + h) * (R + h) - (R + H) * (R + H));  // Pythagoras
  // Slightly steeper than the tangent: two nearly equal hits around the tangent point.
  const ShellHits<double> in = intersect_shell(R, h, H, mt * (1.0 + 1e-9));
  ASSERT_EQ(in.count, 2);
  EXPECT_LT(in.t_near, t_tangent);
  EXPECT_GT(in.t_far, t_tangent);
  EXPECT_NEAR(in.t_near, t_tangent, 20.0);
  EXPECT_NEAR(in.t_far, t_tangent, 20.0);
  // Slightly shallower: a miss.
  EXPECT_EQ(intersect_shell(R, h, H, mt * (1.0 - 1e-9)).count, 0);
  // NaN never yields hits.
  EXPECT_EQ(intersect_shell(R, h, H, std::nan("")).count, 0);
  EXPECT_EQ(intersect_shell(R, std::nan(""), H, -0.5).count, 0);
}

// ---------------------------------------------------------------------------------
// Float precision: the altitude form in float against the reference for the same
// physical ray (double inputs), and the naive float quadratic as a contrast.

struct FloatCase {
  const char* name;
  double h, H, mu;
  double ref_error_m;  // docs/SOURCES.md value for the altitude form
  double naive_error_m;  // and for the naive form
};

TEST(ShellIntersection, FloatAltitudeFormIsMillimetreAccurate) {
  const FloatCase cases[] = {
      {"camera 2 km, 0.9 deg down, base 1.5 km", 2000.0, 1500.0, mu_from_depression_deg(0.9),
       0.0003, 26.4},
      {"camera 2 m, horizontal, shell 1.5 km", 2.0, 1500.0, 0.0, 0.001, 7.6},
  };
  for (const FloatCase& c : cases) {
    SCOPED_TRACE(c.name);
    const RefHits ref = reference(kR, c.h, c.H, c.mu);
    ASSERT_GE(ref.count, 1);
    const ShellHits<float> f =
        intersect_shell<float>(float(kR), float(c.h), float(c.H), float(c.mu));
    ASSERT_EQ(f.count, ref.count);
    const double err = std::fabs(double(f.t_near) - double(ref.t_near));
    const double naive = std::fabs(double(naive_float_near(float(kR), float(c.h), float(c.H),
                                                           float(c.mu))) -
                                   double(ref.t_near));
    std::printf("  %s: t = %.3f m, float altitude form error %.4f m (ref. %.4f), naive float "
                "error %.2f m (ref. %.1f)\n",
                c.name, double(ref.t_near), err, c.ref_error_m, naive, c.naive_error_m);
    EXPECT_LT(err, 0.01);
    EXPECT_GT(naive, 1.0);  // contrast: the naive Earth-centred float form is metres off
  }
}

// Float over the whole grid (mu step 0.005, rays through the Earth included): the
// altitude form stays within 1 cm + 3e-7 t (a few float ulps of t), except within 1e-4
// of the tangent, where the problem itself is ill conditioned.
TEST(ShellIntersection, FloatSweep) {
  double worst = 0.0;
  const double cams[] = {0.0, 2.0, 1000.0, 2000.0, 10000.0, 100000.0};
  for (double h : cams) {
    for (double H : {1500.0, 10000.0}) {
      for (int i = 0; i <= 400; ++i) {
        const double mu = -1.0 + i * 0.005;
        const float mf = float(mu);
        // Reference for the float-rounded inputs: isolates the algorithm's own error.
        const RefHits ref = reference(double(float(kR)), double(float(h)), double(float(H)),
                                      double(mf));
        const ShellHits<float> f = intersect_shell<float>(float(kR), float(h), float(H), mf);
        if (h > H && std::fabs(double(mf) - tangent_mu(kR, h, H)) < 1e-4) continue;
        ASSERT_EQ(f.count, ref.count) << h << " " << H << " " << mu;
        if (ref.count >= 1) {
          const double e = std::fabs(double(f.t_near) - double(ref.t_near));
          const double tol = 0.01 + 3e-7 * double(ref.t_near);  // ~5 float ulps of t
          worst = std::max(worst, e / tol);
          EXPECT_LE(e, tol) << h << " " << H << " " << mu;
        }
      }
    }
  }
  std::printf("float sweep: worst error / (1 cm + 3e-7 t) = %.3g\n", worst);
}

}  // namespace
