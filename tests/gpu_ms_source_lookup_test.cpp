// The shader's lookups of the multiple-scattering source tables (ms_source_over_mu and
// ms_diffuse_incidence_source in shaders/ms_source_lookup.glsl, over
// renderer/ms_source_textures.h's R32F textures) against
// model::MsSourceTable::lookup in double precision, on the GPU (llvmpipe here): the same
// table, so any difference is the texture's filtering and the float arithmetic. Likewise
// the peak beam (peak_beam_phase, shaders/phase_function.glsl and the model's).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "renderer/gl/egl_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"
#include "renderer/model/ms_source_table.h"
#include "renderer/model/phase_function.h"
#include "renderer/model/slab_flux_table.h"
#include "renderer/ms_source_textures.h"

namespace cloudsvc {
namespace {

struct Input {
  float tau_a, tau_b, mu_s, mu_w, phi_deg;
  float cos_theta = 0.0f, tau = 0.0f;  // the peak beam's inputs
  float diffuse = 0.0f;                // 1: the slab's diffuse transmittance, 0: its beam's at mu_s
                                       // (2: the diffuse one, and the diffuse incidence table)
};

constexpr double kDropletUm = 20.0;

std::vector<std::array<float, 4>> run_gpu(const std::vector<Input>& in) {
  static gl::EglContext context;
  static gl::ShaderProgram prog = gl::ShaderProgram::compute("test_ms_source_lookup.comp");
  static MsSourceTextures texture;
  std::vector<float> a, b;
  for (const Input& x : in) {
    a.insert(a.end(), {x.tau_a, x.tau_b, x.mu_s, x.mu_w});
    b.insert(b.end(), {x.phi_deg, x.cos_theta, x.tau, x.diffuse});
  }
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(in.size() * 4 * sizeof(float));
  gl::Buffer ba = gl::make_buffer(bytes, a.data(), GL_STATIC_DRAW);
  gl::Buffer bb = gl::make_buffer(bytes, b.data(), GL_STATIC_DRAW);
  gl::Buffer bo = gl::make_buffer(bytes, nullptr, GL_DYNAMIC_READ);
  prog.use();
  texture.bind();
  glUniform1ui(prog.uniform("u_count"), static_cast<GLuint>(in.size()));
  const model::JdDParams p = model::jdd_params(kDropletUm);
  glUniform4f(prog.uniform("u_phase"), static_cast<float>(p.g_hg), static_cast<float>(p.g_d), static_cast<float>(p.alpha),
              static_cast<float>(p.w_d));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_A, ba.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_B, bb.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_OUTPUT, bo.id());
  glDispatchCompute(static_cast<GLuint>((in.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::array<float, 4>> out(in.size());
  glGetNamedBufferSubData(bo.id(), 0, bytes, out.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return out;
}

// The GPU's source values (out[i][0]) against the double lookup of `table` at the same
// float inputs: each within 1 % (plus 1e-3 of the table's largest value, for the texture
// filter's 8-bit weights between nodes of very different size), and no systematic
// difference (the mean difference below 1e-3 of the mean).
void expect_source_lookups_match(const std::vector<Input>& in, const std::vector<std::array<float, 4>>& out,
                                 const model::MsSourceTable& table, bool diffuse_incidence, const char* what) {
  const double peak = *std::max_element(table.values().begin(), table.values().end());
  double worst = 0.0, bias = 0.0, sum_ref = 0.0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Input& x = in[i];
    const double ref = diffuse_incidence ? table.lookup(x.tau_a, x.tau_b, 1.0, x.mu_w, 0.0)
                                         : table.lookup(x.tau_a, x.tau_b, x.mu_s, x.mu_w, x.phi_deg);
    ASSERT_TRUE(std::isfinite(out[i][0]));
    EXPECT_NEAR(out[i][0], ref, 0.01 * ref + 1e-3 * peak)
        << "tau_a " << x.tau_a << " tau_b " << x.tau_b << " mu_s " << x.mu_s << " mu_w " << x.mu_w << " phi " << x.phi_deg;
    worst = std::max(worst, std::abs(out[i][0] - ref) / (ref + 1e-3 * peak));
    bias += out[i][0] - ref;
    sum_ref += ref;
  }
  std::printf("GPU vs double %s over %zu points: worst relative difference %.2e, mean difference %.2e of the mean\n",
              what, in.size(), worst, bias / sum_ref);
  EXPECT_LT(std::abs(bias / sum_ref), 1e-3) << "a systematic difference";
}

// Random points over the sun table's range and beyond it (thinner and thicker slabs, the
// sun below 84 degrees), and the depth coordinate within 1e-5.
TEST(MsSourceLookup, GpuMatchesTheDoubleLookup) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Input> in;
  for (int i = 0; i < 4000; ++i) {
    const double tau = 0.05 * std::pow(2.0, 14.0 * u(rng));  // 0.05 .. 800
    const double x = u(rng);
    in.push_back({static_cast<float>(tau * x), static_cast<float>(tau * (1.0 - x)), static_cast<float>(u(rng)),
                  static_cast<float>(2.0 * u(rng) - 1.0), static_cast<float>(180.0 * u(rng))});
    // scattering angles from the forward peak (1e-4 deg) to backwards, tau 0..40
    const double theta = std::pow(10.0, -4.0 + 6.26 * u(rng)) * M_PI / 180.0;
    in.back().cos_theta = static_cast<float>(std::cos(std::min(theta, M_PI)));
    in.back().tau = static_cast<float>(40.0 * u(rng) * u(rng));
  }
  const std::vector<std::array<float, 4>> out = run_gpu(in);
  for (std::size_t i = 0; i < in.size(); ++i)
    EXPECT_NEAR(out[i][1], model::ms_depth_coordinate(in[i].tau_a, in[i].tau_b), 1e-5)
        << "tau_a " << in[i].tau_a << " tau_b " << in[i].tau_b;
  expect_source_lookups_match(in, out, model::ms_source_table(), false, "sun table");
}

// The diffuse incidence table likewise, optical depths 0.05 .. 800.
TEST(MsSourceLookup, GpuDiffuseIncidenceTableMatchesTheDoubleLookup) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Input> in;
  for (int i = 0; i < 4000; ++i) {
    const double tau = 0.05 * std::pow(2.0, 14.0 * u(rng));
    const double x = u(rng);
    Input v{static_cast<float>(tau * x), static_cast<float>(tau * (1.0 - x)), 1.0f,
            static_cast<float>(2.0 * u(rng) - 1.0), 0.0f};
    v.diffuse = 2.0f;
    in.push_back(v);
  }
  expect_source_lookups_match(in, run_gpu(in), model::ms_diffuse_incidence_table(), true, "diffuse incidence table");
}

// The peak beam in float against double at the same float inputs: within 1e-3 relative
// (float's HG denominator near the forward peak, (1 - g)^2 + 2 g (1 - mu), keeps it).
TEST(MsSourceLookup, GpuPeakBeamMatchesTheModel) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Input> in;
  for (int i = 0; i < 4000; ++i) {
    Input x{1.0f, 1.0f, 0.5f, 0.0f, 0.0f};
    const double theta = std::pow(10.0, -4.0 + 6.26 * u(rng)) * M_PI / 180.0;
    x.cos_theta = static_cast<float>(std::cos(std::min(theta, M_PI)));
    x.tau = static_cast<float>(40.0 * u(rng) * u(rng));
    in.push_back(x);
  }
  const std::vector<std::array<float, 4>> out = run_gpu(in);
  const model::JdDParams p = model::jdd_params(kDropletUm);
  double worst = 0.0, bias = 0.0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const double ref = model::peak_beam_phase(in[i].cos_theta, in[i].tau, p);
    ASSERT_TRUE(std::isfinite(out[i][2]));
    const double rel = (out[i][2] - ref) / ref;
    worst = std::max(worst, std::abs(rel));
    bias += rel;
    EXPECT_NEAR(out[i][2], ref, 1e-3 * ref) << "cos " << in[i].cos_theta << " tau " << in[i].tau;
  }
  std::printf("GPU vs double peak beam over %zu points: worst relative difference %.2e, mean %.2e\n", in.size(), worst,
              bias / in.size());
}

// The slab transmittances (shaders/slab_transmittance.glsl) against the model's lookups
// of the same table at the same float inputs, over optical depths 0 .. 2000 (below, inside
// and beyond the table's nodes) and sun cosines 0.01 .. 1: within 1e-5 plus 1e-4 relative
// (float arithmetic only).
TEST(MsSourceLookup, GpuSlabTransmittanceMatchesTheModel) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Input> in;
  for (int i = 0; i < 4000; ++i) {
    Input x{0.0f, 0.0f, static_cast<float>(0.01 + 0.99 * u(rng)), 0.0f, 0.0f};
    const double tau = i % 50 == 0 ? 0.0 : 0.01 * std::pow(2.0, 17.6 * u(rng));  // 0.01 .. 2000
    x.tau_a = static_cast<float>(tau * 0.3);
    x.tau_b = static_cast<float>(tau) - x.tau_a;
    x.diffuse = i % 2 == 0 ? 1.0f : 0.0f;
    in.push_back(x);
  }
  const std::vector<std::array<float, 4>> out = run_gpu(in);
  double worst = 0.0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Input& x = in[i];
    const double tau = static_cast<double>(x.tau_a + x.tau_b);  // the sum the shader forms, in float
    const double ref = x.diffuse > 0.5f ? model::slab_diffuse_transmittance(tau) : model::slab_beam_transmittance(tau, x.mu_s);
    ASSERT_TRUE(std::isfinite(out[i][3]));
    EXPECT_NEAR(out[i][3], ref, 1e-5 + 1e-4 * ref) << "tau " << tau << " mu_s " << x.mu_s << " diffuse " << x.diffuse;
    worst = std::max(worst, std::abs(out[i][3] - ref) / ref);
  }
  std::printf("GPU vs double slab transmittance over %zu points: worst relative difference %.2e\n", in.size(), worst);
}

}  // namespace
}  // namespace cloudsvc
