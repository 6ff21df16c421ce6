// Float (GLSL, on the GPU: llvmpipe here) vs double (geo::intersect_shell) precision of the
// renderer's ray / shell intersection and altitude_of at grazing angles (issue "Accuracy"
// part 4; docs/STABILITY.md). Inputs are rounded to float once and the double reference
// uses those same float values, so the errors are those of the shader's arithmetic.
// Bounds (docs/SOURCES.md, "Ray / shell intersection in float"): camera 2 km looking 0.9 deg down at a 1.5 km
// shell, and camera 2 m with a horizontal ray to a 1.5 km shell: < 0.01 m; in general
// < 0.01 m + 3e-7 t. Within 0.1 deg of the tangent the problem itself is ill-conditioned
// (dt/dmu -> infinity): there the bound adds the error that rounding b'^2 and c to float
// (relative 2^-24 each, x8 margin) causes in sqrt(b'^2 - c).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "geodesy/shell_intersection.h"
#include "renderer/gl/egl_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"

namespace cloudsvc {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kFloatEps = 0x1.0p-24;  // float unit roundoff

struct Case {
  float R, h, H, mu;      // m, m, m, cos(zenith): the float inputs
  float t, dx, dz;        // altitude sample distance (m) and float ray direction
  double tangent_off_deg; // elevation minus the tangent elevation (NaN: no tangent)
  std::string group;
};

struct GpuOut { float t0, t1, alt, pad; };

std::vector<GpuOut> run_gpu(const std::vector<Case>& cases) {
  static gl::EglContext context;
  static gl::ShaderProgram prog = gl::ShaderProgram::compute("test_shell_intersection.comp");
  std::vector<float> geom, point;
  for (const Case& c : cases) {
    geom.insert(geom.end(), {c.R, c.h, c.H, c.mu});
    point.insert(point.end(), {c.t, c.dx, c.dz, 0.0f});
  }
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(cases.size() * sizeof(GpuOut));
  gl::Buffer bg = gl::make_buffer(bytes, geom.data(), GL_STATIC_DRAW);
  gl::Buffer bp = gl::make_buffer(bytes, point.data(), GL_STATIC_DRAW);
  gl::Buffer bo = gl::make_buffer(bytes, nullptr, GL_DYNAMIC_READ);
  prog.use();
  glUniform1ui(prog.uniform("u_count"), static_cast<GLuint>(cases.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_A, bg.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_B, bp.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_OUTPUT, bo.id());
  glDispatchCompute(static_cast<GLuint>((cases.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<GpuOut> out(cases.size());
  glGetNamedBufferSubData(bo.id(), 0, bytes, out.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return out;
}

// Cases for one camera altitude h and shell altitude H: horizontal and +-0.01..0.9 deg about
// it, steep rays, and (camera above the shell) rays around the tangent elevation.
void add_cases(std::vector<Case>& out, double R, double h, double H) {
  std::vector<std::pair<double, double>> elev;  // (elevation deg, offset from tangent)
  for (double e : {0.0, 0.01, -0.01, 0.1, -0.1, 0.9, -0.9, 5.0, -5.0, 30.0, -30.0, 89.9, -89.9})
    elev.push_back({e, NAN});
  if (h > H) {
    const double et = -std::acos((R + H) / (R + h)) / kDeg;  // tangent elevation, deg
    for (double d : {-0.9, -0.1, -0.01, -0.001, -1e-4, 0.0, 1e-4, 0.001, 0.01, 0.1, 0.9}) elev.push_back({et + d, d});
  }
  char group[64];
  std::snprintf(group, sizeof group, "cam %g m, shell %g m", h, H);
  for (const auto& [e, off] : elev) {
    const float mu = static_cast<float>(std::sin(e * kDeg));
    const float dx = static_cast<float>(std::cos(e * kDeg));
    const geo::ShellHits<double> ref = geo::intersect_shell<double>(float(R), float(h), float(H), mu);
    std::vector<double> ts = {1.0, 100.0, 1.0e4};
    if (ref.count >= 1) ts.push_back(ref.t_near);
    if (ref.count == 2) ts.push_back(ref.t_far);
    for (double t : ts)
      out.push_back({float(R), float(h), float(H), mu, float(t), dx, static_cast<float>(std::sin(e * kDeg)), off, group});
  }
}

struct GroupStats {
  double max_err = 0.0, max_err_t = 0.0, max_ratio = 0.0, max_alt_err = 0.0, max_tangent_err = 0.0;
  int rays = 0, ambiguous = 0;
};

TEST(GpuShellPrecision, FloatShaderMatchesDoubleWithinBounds) {
  std::vector<Case> cases;
  for (double R : {6360000.0, 6378137.0})
    for (double h : {2.0, 2000.0, 10000.0, 100000.0})
      for (double H : {1500.0, 10000.0}) add_cases(cases, R, h, H);
  const std::vector<GpuOut> gpu = run_gpu(cases);
  ASSERT_EQ(gpu.size(), cases.size());
  std::vector<std::pair<std::string, GroupStats>> groups;
  auto stats_of = [&](const std::string& g) -> GroupStats& {
    for (auto& p : groups) if (p.first == g) return p.second;
    groups.push_back({g, {}});
    return groups.back().second;
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const GpuOut& o = gpu[i];
    GroupStats& st = stats_of(c.group);
    const double R = c.R, h = c.h, H = c.H, mu = c.mu;
    const geo::ShellHits<double> ref = geo::intersect_shell<double>(R, h, H, mu);
    // GPU hits at t >= 0, in order.
    std::vector<double> g;
    if (o.t1 >= 0.0f) { if (o.t0 >= 0.0f) g.push_back(o.t0); g.push_back(o.t1); }
    std::vector<double> r;
    if (ref.count >= 1) r.push_back(ref.t_near);
    if (ref.count == 2) r.push_back(ref.t_far);
    const double b = -(R + h) * mu, cc = (h - H) * (2 * R + h + H), disc = b * b - cc;
    const double rounding = 8.0 * kFloatEps * (b * b + std::abs(cc));  // float error of disc, m^2
    const bool near_tangent = std::abs(c.tangent_off_deg) <= 0.1;
    ++st.rays;
    if (g.size() != r.size()) {
      // Hit/miss may flip only where the float rounding of disc can change its sign.
      EXPECT_LE(std::abs(disc), rounding) << c.group << " mu " << mu << ": GPU " << g.size() << " hits, double " << r.size();
      ++st.ambiguous;
      continue;
    }
    for (size_t k = 0; k < r.size(); ++k) {
      const double err = std::abs(g[k] - r[k]);
      double tol = 0.01 + 3e-7 * r[k];
      if (near_tangent) {
        tol += rounding / (2.0 * std::sqrt(std::max(disc, rounding)));
        st.max_tangent_err = std::max(st.max_tangent_err, err);
      } else {
        if (r[k] <= 1.0e6 && err > st.max_err) { st.max_err = err; st.max_err_t = r[k]; }  // visible range
        st.max_ratio = std::max(st.max_ratio, err / tol);
      }
      EXPECT_LE(err, tol) << c.group << " R " << R << " elevation " << std::asin(mu) / kDeg << " deg, t " << r[k];
    }
    // altitude_of at p = t d (the float product the shader forms, evaluated in double).
    const double px = double(c.t) * c.dx, pz = double(c.t) * c.dz;
    const double alt_ref = std::hypot(px, pz + R + h) - R;
    const double alt_err = std::abs(o.alt - alt_ref);
    st.max_alt_err = std::max(st.max_alt_err, alt_err);
    // The result is a float: allow 2 ulp of the altitude itself (7.8 mm ulp at 100 km).
    EXPECT_LE(alt_err, 0.01 + 3e-7 * c.t + 0x1.0p-22 * std::abs(alt_ref)) << c.group << " t " << c.t << " mu " << mu;
  }
  std::printf("\n| camera / shell | rays | max t err, t <= 1000 km (m) | at t (m) | max err / (0.01 m + 3e-7 t), all t | near-tangent max err (m) | hit/miss flips | max altitude_of err (m) |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, s] : groups)
    std::printf("| %s | %d | %.2e | %.0f | %.3f | %.2e | %d | %.2e |\n", name.c_str(), s.rays, s.max_err, s.max_err_t,
                s.max_ratio, s.max_tangent_err, s.ambiguous, s.max_alt_err);
}

// The two reference cases of docs/SOURCES.md, asserted on their own.
TEST(GpuShellPrecision, ReferenceCasesWithinOneCentimetre) {
  const double R = 6360000.0;
  const float mu_down = static_cast<float>(std::sin(-0.9 * kDeg));
  const std::vector<Case> cases = {
      {float(R), 2000.0f, 1500.0f, mu_down, 0.0f, 1.0f, 0.0f, NAN, "2 km, 0.9 deg down, shell 1.5 km"},
      {float(R), 2.0f, 1500.0f, 0.0f, 0.0f, 1.0f, 0.0f, NAN, "2 m horizontal, shell 1.5 km"}};
  const std::vector<GpuOut> gpu = run_gpu(cases);
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const geo::ShellHits<double> ref = geo::intersect_shell<double>(c.R, c.h, c.H, c.mu);
    ASSERT_GE(ref.count, 1) << c.group;
    ASSERT_GE(gpu[i].t1, 0.0f) << c.group;
    const double t_gpu = gpu[i].t0 >= 0.0f ? gpu[i].t0 : gpu[i].t1;
    // The naive float quadratic on Earth-centred coordinates, for the record.
    const float oz = c.R + c.h, bn = 2.0f * oz * c.mu, cn = oz * oz - (c.R + c.H) * (c.R + c.H);
    const float dn = std::sqrt(std::max(bn * bn - 4.0f * cn, 0.0f));
    const float tn0 = (-bn - dn) / 2.0f, tn1 = (-bn + dn) / 2.0f;
    const double t_naive = tn0 >= 0.0f ? tn0 : tn1;
    std::printf("%s: t = %.4f m, GPU error %.2e m, naive float (CPU) error %.2f m\n", c.group.c_str(), ref.t_near,
                std::abs(t_gpu - ref.t_near), std::abs(t_naive - ref.t_near));
    EXPECT_LT(std::abs(t_gpu - ref.t_near), 0.01) << c.group;
  }
}

}  // namespace
}  // namespace cloudsvc
