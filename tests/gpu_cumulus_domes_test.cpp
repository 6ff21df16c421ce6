// The dome top the GPU reads for a cumulus layer (shaders/cumulus_domes.glsl: rings filled by
// renderer/placement_rings.h, sub-grid noise, level-of-detail blend) against the CPU's
// reading of the same rings (weather::DomeTopSampler, double): along lines from the nadir
// out past the last ring, at places including a pole and the antimeridian.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "renderer/dome_layer_gpu.h"
#include "renderer/gl/egl_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"
#include "renderer/placement_rings.h"
#include "weather/weather_map.h"

namespace cloudsvc {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(GpuCumulusDomes, ReadTheSameTopAsTheCpuThroughEveryLevelOfDetail) {
  static gl::EglContext context;
  const double c = 0.4;
  const std::uint32_t seed = 13;
  const weather::CloudPlacement cp(weather::dome_placement_params(c), weather::kDomeShellRadius_m, seed);
  const weather::DomeWarp warp(seed);
  const weather::DomeSubgrid subgrid(seed);
  const weather::RingLayout layout = weather::dome_ring_layout();
  const auto cov = [c](const glm::dvec3&) { return c; };
  const weather::DomeTopSampler cpu(cp, warp, subgrid, layout, cov);
  // a uniform weather map: the neutral 0.5 keeps the layer's own coverage
  const std::vector<float> map(4 * 4 * 2, 0.5f);
  gl::Texture map_tex = gl::make_texture_2d(GL_RGBA32F, 4, 2, GL_REPEAT, GL_CLAMP_TO_EDGE);
  glTextureSubImage2D(map_tex.id(), 0, 0, 0, 4, 2, GL_RGBA, GL_FLOAT, map.data());
  glBindTextureUnit(gpu::tex::WEATHER_MAP, map_tex.id());
  glBindTextureUnit(gpu::tex::WEATHER_MAP_NEXT, map_tex.id());
  PlacementRings rings(layout, 1);
  gl::ShaderProgram prog = gl::ShaderProgram::compute("test_cumulus_domes.comp");
  for (auto [lat, lon] : {std::pair{47.4, 8.5}, {89.97, 10.0}, {-20.0, 179.99}}) {
    const double la = lat * kPi / 180.0, lo = lon * kPi / 180.0;
    const glm::dvec3 up(std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la));
    const glm::dvec3 camera = (weather::kDomeShellRadius_m + 9000.0) * up;
    const weather::DomeRings where = weather::dome_rings_for(layout, camera);
    RingInputs in;
    in.centre = where.anchor;
    in.layer_coverage = c;
    in.map_height = 2.0f;
    in.pole_south = in.pole_north = glm::vec4(0.5f);
    for (int k = 0; k < layout.rings; ++k) {
      in.origin = where.origin[k];
      rings.fill(0, k, cp, warp, in);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    const DomeLayerGpu layer = dome_layer_gpu(where, layout, cp, subgrid, 0);
    // points along two lines through the nadir, 0 to 90 km out (every level of detail)
    const glm::dvec3 e = where.plane.e, n = where.plane.n;
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 3000; ++i) {
      const double d = 30.0 * i;
      const glm::dvec3 dir = i % 2 ? glm::normalize(e + 0.3 * n) : glm::normalize(-0.6 * e + n);
      points.push_back(weather::kDomeShellRadius_m * glm::normalize(camera / glm::length(camera) * weather::kDomeShellRadius_m + d * dir));
    }
    std::vector<float> pts;
    for (const glm::dvec3& p : points) {
      const glm::dvec3 q = p - where.anchor;
      pts.insert(pts.end(), {float(q.x), float(q.y), float(q.z), float(c)});
    }
    const GLsizeiptr bytes = static_cast<GLsizeiptr>(pts.size() * sizeof(float));
    gl::Buffer bl = gl::make_buffer(sizeof layer, &layer, GL_STATIC_DRAW);
    gl::Buffer bp = gl::make_buffer(bytes, pts.data(), GL_STATIC_DRAW);
    gl::Buffer bo = gl::make_buffer(bytes, nullptr, GL_DYNAMIC_READ);
    prog.use();
    glUniform1ui(prog.uniform("u_count"), static_cast<GLuint>(points.size()));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::DOME_LAYERS, bl.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_INPUT_B, bp.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::ssbo::TEST_OUTPUT, bo.id());
    glBindTextureUnit(gpu::tex::DOME_RINGS, rings.texture());
    glDispatchCompute(static_cast<GLuint>((points.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> out(pts.size());
    glGetNamedBufferSubData(bo.id(), 0, bytes, out.data());
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    int differ = 0, inside = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double want = cpu.top_m(where, points[i], c), got = out[4 * i];
      inside += want > 0.0;
      const double err = std::abs(got - want);
      if (err > 1.0) ++differ;  // metres: a sub-grid noise value or a cloud apart
      else worst = std::max(worst, err);
    }
    std::printf("%.2f, %.2f: %zu points, %d under a cloud; %d differ by > 1 m, the rest within %.3f m\n", lat, lon,
                points.size(), inside, differ, worst);
    EXPECT_LE(differ, static_cast<int>(points.size() / 200)) << lat;
    EXPECT_LT(worst, 0.2) << lat;
    EXPECT_GT(inside, static_cast<int>(points.size() / 10)) << lat;
  }
}

}  // namespace
}  // namespace cloudsvc
