// The march's GLSL coverage-pyramid bound (shaders/coverage_pyramid.glsl, float) against the
// CPU one (renderer/coverage_pyramid.cpp, double) on the same pyramid: for random caps over
// the globe, at the poles and across the antimeridian, the GPU bound is never below the CPU
// bound computed for a slightly smaller cap (float rounding of the cap's edges may pick a
// neighbouring cell: the GPU may be more conservative, never less), and equals the CPU
// bound for almost all caps.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

#include "renderer/coverage_pyramid.h"
#include "renderer/gl/egl_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"
#include "weather/weather_map.h"

namespace cloudsvc::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(GpuCoveragePyramid, ShaderBoundMatchesTheCpuBound) {
  static gl::EglContext context;
  static gl::ShaderProgram prog = gl::ShaderProgram::compute("test_coverage_pyramid.comp");
  const weather::WeatherMap a = weather::generate_procedural_map(31, 720, 360);
  const weather::WeatherMap b = weather::generate_procedural_map(32, 720, 360);
  const CoveragePyramid p = build_coverage_pyramid(a, &b);
  const std::vector<std::uint32_t> words = pack_for_gpu(p);
  ASSERT_FALSE(words.empty());

  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<float> caps;
  std::vector<double> lat, lon, rad;
  for (int k = 0; k < 4096; ++k) {
    double la = (u(rng) - 0.5) * kPi, lo = (u(rng) - 0.5) * 2.0 * kPi;
    if (k % 8 == 1) la = (u(rng) < 0.5 ? -1.0 : 1.0) * (0.5 * kPi - 0.03 * u(rng));
    if (k % 8 == 2) lo = (u(rng) < 0.5 ? -1.0 : 1.0) * (kPi - 0.03 * u(rng));
    const double r = std::exp(std::log(1e-5) + u(rng) * (std::log(0.5) - std::log(1e-5)));
    const float fla = static_cast<float>(la), flo = static_cast<float>(lo), fr = static_cast<float>(r);
    caps.insert(caps.end(), {fla, flo, fr, 0.0f});
    lat.push_back(fla);
    lon.push_back(flo);
    rad.push_back(fr);
  }
  const size_t n = lat.size();
  gl::Buffer pyramid = gl::make_buffer(static_cast<GLsizeiptr>(words.size() * 4), words.data(), GL_STATIC_DRAW);
  gl::Buffer in = gl::make_buffer(static_cast<GLsizeiptr>(caps.size() * 4), caps.data(), GL_STATIC_DRAW);
  gl::Buffer out = gl::make_buffer(static_cast<GLsizeiptr>(n * 4), nullptr, GL_DYNAMIC_READ);
  prog.use();
  glUniform1ui(prog.uniform("u_count"), static_cast<GLuint>(n));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::COVERAGE_PYRAMID, pyramid.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_A, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_OUTPUT, out.id());
  glDispatchCompute(static_cast<GLuint>((n + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(n);
  glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(n * 4), gpu.data());
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  int equal = 0;
  for (size_t i = 0; i < n; ++i) {
    const float cpu = pyramid_max_in_cap(p, lat[i], lon[i], rad[i]);
    // float rounding of the cap's edges (~1e-6 of a texel at most) may pick the next cell
    const float cpu_inner = pyramid_max_in_cap(p, lat[i], lon[i], rad[i] * (1.0 - 1e-5));
    ASSERT_GE(gpu[i], cpu_inner) << "cap " << i << ": lat " << lat[i] << " lon " << lon[i] << " radius " << rad[i];
    equal += gpu[i] == cpu ? 1 : 0;
  }
  std::printf("GPU bound equal to the CPU bound for %d of %zu caps\n", equal, n);
  EXPECT_GE(equal, static_cast<int>(0.99 * static_cast<double>(n)));
}

}  // namespace
}  // namespace cloudsvc::test
