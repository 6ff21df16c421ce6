// The dome rings the GPU fills (renderer/placement_rings.h, shaders/placement_rings.comp)
// against the CPU's (weather::dome_ring_texel, weather/cumulus_domes.h) at the same texels:
// the warped unit-aspect dome top of each ring's own levels and the covered fraction of the
// finer ones, with each cloud accepted by a real weather map read at its own centre, in a
// wind-turned field frame, at places including a pole and the antimeridian.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/gl/egl_context.h"
#include "renderer/gl/gl_objects.h"
#include "renderer/gpu_interface.h"
#include "renderer/placement_rings.h"
#include "weather/cumulus_domes.h"
#include "weather/dome_rings.h"
#include "weather/placement_rings.h"
#include "weather/weather_map.h"

namespace cloudsvc {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(GpuPlacementRings, MatchTheCpuPlacementAtTheirTexels) {
  static gl::EglContext context;
  const double R = weather::kDomeShellRadius_m, layer_coverage = 0.45;
  const weather::CloudPlacement cp(weather::dome_placement_params(layer_coverage), R, 5);
  const weather::DomeWarp warp(5);
  const weather::WeatherMap map = weather::generate_procedural_map(9, 256, 128);
  gl::Texture map_tex = gl::make_texture_2d(GL_RGBA32F, map.width, map.height, GL_REPEAT, GL_CLAMP_TO_EDGE);
  glTextureSubImage2D(map_tex.id(), 0, 0, 0, map.width, map.height, GL_RGBA, GL_FLOAT, map.rgba.data());
  glBindTextureUnit(gpu::tex::WEATHER_MAP, map_tex.id());
  glBindTextureUnit(gpu::tex::WEATHER_MAP_NEXT, map_tex.id());
  float south[4], north[4];
  map.pole_value(false, south);
  map.pole_value(true, north);
  // a field turned by the wind: 0.3 rad about an axis through (1, 2, 3)
  const glm::dmat3 field_to_ecef = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.3, glm::normalize(glm::dvec3(1.0, 2.0, 3.0))));
  const auto coverage = [&](const glm::dvec3& x) {
    const glm::dvec3 q = field_to_ecef * x;
    const double lat = std::atan2(q.z, std::hypot(q.x, q.y)) * 180.0 / kPi, lon = std::atan2(q.y, q.x) * 180.0 / kPi;
    float w[4];
    map.sample(lat, lon, w);
    return static_cast<double>(weather::local_coverage(static_cast<float>(layer_coverage), w[0]));
  };
  weather::RingLayout layout = weather::dome_ring_layout();
  layout.size = 128;  // small: the test reads back whole slices
  PlacementRings rings(layout, 1);
  for (auto [lat, lon] : {std::pair{47.4, 8.5}, {89.995, 40.0}, {-20.0, 179.99}}) {
    const double la = lat * kPi / 180.0, lo = lon * kPi / 180.0;
    const glm::dvec3 camera = (R + 2500.0) * glm::transpose(field_to_ecef) *
                              glm::dvec3(std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la));
    const weather::DomeRings dome_rings = weather::dome_rings_for(layout, camera);
    const glm::dvec3 C = dome_rings.anchor;
    RingInputs in;
    in.centre = C;
    in.field_to_ecef = field_to_ecef;
    in.layer_coverage = layer_coverage;
    in.map_height = static_cast<float>(map.height);
    in.pole_south = glm::vec4(south[0], south[1], south[2], south[3]);
    in.pole_north = glm::vec4(north[0], north[1], north[2], north[3]);
    const weather::RingPlane plane = weather::ring_plane(C);
    for (int ring = 0; ring < layout.rings; ++ring) {
      in.origin = dome_rings.origin[ring];
      rings.fill(0, ring, cp, warp, in);
      std::vector<float> texels(static_cast<std::size_t>(layout.size) * layout.size * 2);
      glGetTextureSubImage(rings.texture(), 0, 0, 0, rings.slice(0, ring), layout.size, layout.size, 1, GL_RG, GL_FLOAT,
                           static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
      ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      int compared = 0, mismatched = 0, covered = 0;
      double worst_below = 0.0, worst_top = 0.0;
      for (int j = 3; j < layout.size; j += 9)
        for (int i = 5; i < layout.size; i += 9) {
          const glm::dvec2 uv = in.origin + weather::ring_texel_uv(layout, ring, i, j);
          const weather::DomeRingTexel cpu = weather::dome_ring_texel_at(cp, warp, layout, plane, C, ring, uv, coverage);
          const std::size_t k = (static_cast<std::size_t>(j) * layout.size + i) * 2;
          ++compared;
          covered += cpu.top_m > 0.0;
          const double d = std::abs(texels[k] - cpu.top_m);
          if (d > 0.5) ++mismatched;  // metres: another cloud's top
          else worst_top = std::max(worst_top, d);
          worst_below = std::max(worst_below, std::abs(texels[k + 1] - cpu.covered_below));
        }
      std::printf("%.3f, %.2f ring %d (%.0f m texels, levels %d..%d): %d of %d texels under a cloud, %d differ, the rest "
                  "within %.3f m; covered below: worst difference %.1e\n",
                  lat, lon, ring, weather::ring_texel_m(layout, ring), weather::ring_first_level(layout, cp.params(), ring),
                  cp.params().levels - 1, covered, compared, mismatched, worst_top,
                  worst_below);
      // a cloud's acceptance reads the map at its centre: the GPU's bilinear weights (8-bit
      // fractions) can tip a candidate whose hash is within ~1e-3 of its probability
      EXPECT_LE(mismatched, compared / 100) << lat << " " << lon << " ring " << ring;
      EXPECT_LT(worst_top, 0.1);
      EXPECT_LT(worst_below, 5e-3);
      EXPECT_GT(covered, compared / 50) << "every ring draws clouds";
    }
  }
}

}  // namespace
}  // namespace cloudsvc
