// CPU mirror of shaders/temporal_uniforms.glsl (std140, vec4/mat4 members only). Keep the
// two in sync.
#pragma once

#include <glm/glm.hpp>

namespace cloudsvc {

// Index of the ground's transform in TemporalUniforms::reproject (0..3 are cloud layers).
constexpr int kGroundTransform = 4;

struct TemporalUniforms {
  glm::mat4 reproject[5];  // current local -> previous local (m): layers 0..3, ground
  glm::vec4 prev_forward;  // previous camera axes in the previous local frame
  glm::vec4 prev_right;
  glm::vec4 prev_up;
  glm::vec4 prev_view;     // tan(hfov/2), tan(vfov/2)
  glm::ivec4 grid;         // stride, offset x, offset y, history valid
  glm::ivec4 buffer_size;  // cloud buffer w, h, divisor, neighbourhood clamp
  glm::vec4 blend;         // minimum weight of a fresh sample, camera still (1/0)
};

static_assert(sizeof(TemporalUniforms) == 5 * 64 + 7 * 16, "std140 layout");

}  // namespace cloudsvc
