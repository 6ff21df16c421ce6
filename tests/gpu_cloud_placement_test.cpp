// The GPU's cloud placement (shaders/cloud_placement.glsl) against the CPU's
// (weather/cloud_placement.cpp): the same clouds, evaluated in float relative to a centre
// on the shell. Unit-aspect dome tops agree within float error over grids around places on the globe,
// the poles and the antimeridian included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "renderer/gl/egl_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"
#include "renderer/placement_rings.h"
#include "weather/cloud_placement.h"

namespace cloudsvc {
namespace {

constexpr double kFloor_m = 3000.0;  // the dome top's floor: negative values compared down to it

// The frame around C with every level's acceptance at one coverage.
PlacementFrameGpu frame_for(const weather::CloudPlacement& cp, const glm::dvec3& C, double coverage) {
  PlacementFrameGpu f = placement_frame_gpu(cp, C);
  for (int k = 0; k < f.levels; ++k) f.acceptance[k] = static_cast<float>(cp.level_acceptance(k, coverage));
  return f;
}

std::vector<float> run_gpu(const PlacementFrameGpu& frame, const std::vector<glm::dvec3>& rel) {
  static gl::EglContext context;
  static gl::ShaderProgram prog = gl::ShaderProgram::compute("test_cloud_placement.comp");
  std::vector<float> pts;
  for (const glm::dvec3& d : rel) pts.insert(pts.end(), {float(d.x), float(d.y), float(d.z), float(kFloor_m)});
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(rel.size() * 4 * sizeof(float));
  gl::Buffer bf = gl::make_buffer(sizeof frame, &frame, GL_STATIC_DRAW);
  gl::Buffer bp = gl::make_buffer(bytes, pts.data(), GL_STATIC_DRAW);
  gl::Buffer bo = gl::make_buffer(bytes, nullptr, GL_DYNAMIC_READ);
  prog.use();
  glUniform1ui(prog.uniform("u_count"), static_cast<GLuint>(rel.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_A, bf.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_B, bp.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_OUTPUT, bo.id());
  glDispatchCompute(static_cast<GLuint>((rel.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> out(rel.size() * 4);
  glGetNamedBufferSubData(bo.id(), 0, bytes, out.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  std::vector<float> e(rel.size());
  for (std::size_t i = 0; i < rel.size(); ++i) e[i] = out[4 * i];
  return e;
}

TEST(GpuCloudPlacement, MatchesTheCpuPlacementAnywhere) {
  const double R = 6371000.0 + 2000.0, coverage = 0.45;
  const weather::CloudPlacement cp({}, R, 21);
  const auto cov = [coverage](const glm::dvec3&) { return coverage; };
  for (auto [lat, lon] : {std::pair{47.4, 8.5}, {-33.9, 151.2}, {89.99, 0.0}, {-90.0, 0.0}, {0.0, 180.0}, {12.0, -179.99}}) {
    const double la = lat * M_PI / 180.0, lo = lon * M_PI / 180.0;
    const glm::dvec3 up(std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la));
    const glm::dvec3 east = std::abs(up.z) > 0.999 ? glm::dvec3(0, 1, 0) : glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up));
    const glm::dvec3 north = glm::cross(up, east);
    const glm::dvec3 C = R * up;
    std::vector<glm::dvec3> rel;
    std::vector<double> cpu;
    const int n = 48;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::dvec3 p = R * glm::normalize(C + (x - 0.5 * n) * 400.0 * east + (y - 0.5 * n) * 400.0 * north);
        rel.push_back(p - C);
        cpu.push_back(cp.dome_top(p, cov, 0, cp.params().levels, kFloor_m));
      }
    const std::vector<float> gpu = run_gpu(frame_for(cp, C, coverage), rel);
    double worst = 0.0;
    int covered = 0;
    for (std::size_t i = 0; i < cpu.size(); ++i) {
      worst = std::max(worst, std::abs(gpu[i] - cpu[i]));
      covered += cpu[i] > 0.0;
    }
    std::printf("lat %.2f lon %.2f: worst |gpu - cpu| %.2e m, %d of %zu points under a cloud\n", lat, lon, worst,
                covered, cpu.size());
    EXPECT_LT(worst, 0.05) << lat << " " << lon;  // float against double, tops of up to 8 km
    EXPECT_GT(covered, static_cast<int>(cpu.size() / 5));
  }
}

}  // namespace
}  // namespace cloudsvc
